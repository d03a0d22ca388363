!> A point of a continued branch of periodic orbits and its test functions (docs/method.md,
!! "Continuation of periodic orbits", "Stability and test functions"): what
!! `vibrobeam_continuation` keeps of each converged orbit, and the four functions whose
!! sign change between two consecutive points reports a bifurcation there: the tangent's
!! lambda component (fold), det(M + I) (period doubling), |mu|^2 - 1 of the largest
!! complex pair (Neimark-Sacker), the orbit's smallest clearance to the obstacles
!! (grazing).
module vibrobeam_branch_point
   use vibrobeam_kinds, only: dp
   implicit none
   private
   public :: branch_point, bifurcation_point, bifurcation_names, test_count, kind_grazing
   public :: set_test_functions, changes_sign

   !> How many test functions a branch point carries (and kinds of bifurcation there are).
   integer, parameter :: test_count = 4
   !> The kinds of bifurcation, in the order of the test functions.
   character(len=*), parameter :: bifurcation_names(test_count) = [character(len=15) :: 'fold', &
                                                                   'period-doubling', 'neimark-sacker', 'grazing']
   !> The kind of a grazing: the smallest clearance through zero.
   integer, parameter :: kind_grazing = 4

   !> One point of the branch: a converged orbit.
   type :: branch_point
      real(dp) :: parameter = 0                   !! lambda
      real(dp), allocatable :: x(:)               !! (U, V) at phase 0
      real(dp), allocatable :: tangent(:)         !! unit tangent in the point's scaled coordinates (2 J + 1)
      real(dp), allocatable :: scale(:)           !! (2 J + 1) the point's scaled coordinates z = scale * (x, lambda)
      real(dp), allocatable :: multipliers(:, :)  !! (2, 2 J) Floquet multipliers, largest modulus first
      real(dp) :: amplitude = 0                   !! largest |u| of the tip over the orbit (m)
      !> the smallest clearance of the contact points to their obstacles over the steps of
      !! the orbit (m; negative: a compliant stop's penetration; huge without obstacles)
      real(dp) :: minimum_gap = huge(1.0_dp)
      real(dp) :: period = 0                      !! the orbit's period, k P dt (s)
      real(dp) :: step = 0                        !! the arclength step that reached it (scaled)
      integer :: iterations = 0                   !! corrector's Newton iterations
      !> the test functions (`set_test_functions`), in the order of `bifurcation_names`
      real(dp) :: tests(test_count) = 0
   end type branch_point

   !> A bifurcation located between two branch points.
   type :: bifurcation_point
      !> 1 fold, 2 period doubling, 3 Neimark-Sacker, 4 grazing (`bifurcation_names`)
      integer :: kind = 0
      real(dp) :: parameter = 0            !! lambda where the test function vanishes
      real(dp) :: amplitude = 0            !! the tip's amplitude there (m)
      integer :: index = 0                 !! the branch point before it (1-based)
      logical :: located = .false.         !! regula falsi converged (else the linear estimate between the points)
   end type bifurcation_point

contains

   !> The test functions of `point` from its unit tangent (scaled, lambda last), its
   !! multipliers and its smallest clearance: the tangent's lambda component (fold);
   !! det(M + I) = prod(1 + mu) (period doubling: a complex pair contributes |1 + mu|^2 > 0);
   !! the largest |mu|^2 - 1 of a complex pair, -1 without one (Neimark-Sacker); the
   !! smallest clearance (grazing, m).
   subroutine set_test_functions(point)
      type(branch_point), intent(inout) :: point
      complex(dp) :: product
      integer :: j
      point%tests(1) = point%tangent(size(point%tangent))
      product = 1
      do j = 1, size(point%multipliers, 2)
         product = product*cmplx(1 + point%multipliers(1, j), point%multipliers(2, j), dp)
      end do
      point%tests(2) = real(product)
      point%tests(3) = -1
      do j = 1, size(point%multipliers, 2)
         if (point%multipliers(2, j) > 0) then
            point%tests(3) = point%multipliers(1, j)**2 + point%multipliers(2, j)**2 - 1
            exit   ! (largest modulus first: the first complex pair is the largest)
         end if
      end do
      point%tests(kind_grazing) = point%minimum_gap
   end subroutine set_test_functions

   !> a and b of strictly opposite signs (without their product, which overflows for the
   !! clearance of a scene without obstacles, huge).
   elemental logical function changes_sign(a, b)
      real(dp), intent(in) :: a, b
      changes_sign = (a < 0 .and. b > 0) .or. (a > 0 .and. b < 0)
   end function changes_sign
end module vibrobeam_branch_point
