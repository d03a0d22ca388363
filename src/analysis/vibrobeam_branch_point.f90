!> A point of a continued branch of periodic orbits and its test functions (docs/method.md,
!! "Continuation of periodic orbits", "Stability and test functions"): what
!! `vibrobeam_continuation` keeps of each converged orbit, and the four functions whose
!! sign change between two consecutive points reports a bifurcation there: the tangent's
!! lambda component (fold), det(M + I) (period doubling), |mu|^2 - 1 of the largest
!! complex pair (Neimark-Sacker), the orbit's smallest clearance to the obstacles
!! (grazing); on a branch of 2k forcing periods also the fifth, set by
!! `vibrobeam_continuation` from the map of k periods (`half_period_test`): where the
!! orbit becomes one of k periods, a branch point of the 2k-period map.
module vibrobeam_branch_point
   use vibrobeam_kinds, only: dp
   implicit none
   private
   public :: branch_point, bifurcation_point, bifurcation_names, test_count, kind_grazing
   public :: kind_fold, kind_doubling, kind_branch_point
   public :: set_test_functions, changes_sign, half_period_test, is_stable

   !> How many test functions a branch point carries (and kinds of bifurcation there are).
   integer, parameter :: test_count = 5
   !> The kinds of bifurcation, in the order of the test functions.
   character(len=*), parameter :: bifurcation_names(test_count) = [character(len=15) :: 'fold', &
                                                                   'period-doubling', 'neimark-sacker', 'grazing', &
                                                                   'branch-point']
   !> The kind of a fold (the tangent's lambda component through zero) and of a period
   !! doubling (det(M + I) through zero).
   integer, parameter :: kind_fold = 1, kind_doubling = 2
   !> The kind of a grazing: the smallest clearance through zero.
   integer, parameter :: kind_grazing = 4
   !> The kind of a branch point of the 2k-period map where its orbit becomes one of k
   !! periods (`half_period_test` through zero; only on a branch of an even period_multiple).
   integer, parameter :: kind_branch_point = 5

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
      !> stable: every |mu| < 1 on a forced branch (0 here); on the backbone of an autonomous
      !! orbit (`vibrobeam_backbone`), whose multipliers lie on the unit circle at best, every
      !! |mu| <= 1 + this, the splitting of its two multipliers at 1 by the monodromy's errors
      real(dp) :: stable_margin = 0
      !> a branch of 2k periods: Phi_k(x) - x, the map of k periods' move of x (2 J)
      real(dp), allocatable :: half_shift(:)
      !> the test functions (`set_test_functions`), in the order of `bifurcation_names`
      real(dp) :: tests(test_count) = 0
   end type branch_point

   !> A bifurcation located between two branch points.
   type :: bifurcation_point
      !> 1 fold, 2 period doubling, 3 Neimark-Sacker, 4 grazing, 5 branch point (`bifurcation_names`)
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

   !> The test function of a branch point of the map of 2k periods, sigma rho -
   !! sqrt(tolerance): rho = ||Phi_k(x) - x||/max(||x||, ||Phi_k(x)||) (`shift` over
   !! `size`, energy norm), how far the map of k periods moves the orbit of 2k periods,
   !! and sigma = +-1 whether it moves it the way it moved the point before (the two phases
   !! of the orbit swap where a branch passes through the branch point). Positive on an
   !! orbit of 2k periods whose phases lie more than sqrt(tolerance) apart; about
   !! -sqrt(tolerance) on one of k periods (its rho is of Newton's tolerance). Near the
   !! branch point (a pitchfork of the 2k-period map) rho grows linearly along the branch,
   !! like the phases' distance c, while lambda moves like c^2: the zero lies where rho =
   !! sqrt(tolerance), within (d lambda/d rho^2) tolerance of the branch point in lambda
   !! (docs/method.md, "Branch switching at a period doubling"). A branch switch accepts a
   !! start that converged where this is positive.
   pure real(dp) function half_period_test(shift, size, same_way, tolerance)
      real(dp), intent(in) :: shift, size, tolerance
      logical, intent(in) :: same_way
      real(dp) :: rho
      rho = shift
      if (size > 0) rho = shift/size
      half_period_test = merge(1.0_dp, -1.0_dp, same_way)*rho - sqrt(tolerance)
   end function half_period_test

   !> The point is stable (branch_point%stable_margin): its largest |mu| < 1, or on a
   !! backbone <= 1 + its margin.
   elemental logical function is_stable(point)
      type(branch_point), intent(in) :: point
      real(dp) :: largest
      largest = 0
      if (size(point%multipliers, 2) > 0) largest = hypot(point%multipliers(1, 1), point%multipliers(2, 1))
      is_stable = largest < 1 .or. (point%stable_margin > 0 .and. largest <= 1 + point%stable_margin)
   end function is_stable

   !> a and b of strictly opposite signs (without their product, which overflows for the
   !! clearance of a scene without obstacles, huge).
   elemental logical function changes_sign(a, b)
      real(dp), intent(in) :: a, b
      changes_sign = (a < 0 .and. b > 0) .or. (a > 0 .and. b < 0)
   end function changes_sign
end module vibrobeam_branch_point
