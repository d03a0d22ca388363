!> The flexibility K^-1 of the clamped-free beam applied in O(J) operations by
!! integrating twice, without factoring K.
!!
!! Why not the band Cholesky of K: K discretizes a fourth-order operator, and its condition
!! number grows like N^4 (about 1e22 at N = 1e5, Hermite). A Cholesky solve with K leaves
!! errors of relative size eps N^4 on smooth vectors, and the lowest eigenvalue computed
!! with it loses all accuracy as N grows (measured with shift-invert Lanczos: omega_1 off by
!! 1.6e-6 at N = 1e4 and by 44 % at N = 1e5; the B-spline K is not even numerically
!! positive definite at N = 1e5). Written in curvatures the same problem is a
!! well-conditioned one (docs/method.md, "Natural modes"):
!!
!! every u of the discrete space (clamped at 0) is determined by its curvature
!! kappa = u'', and u(x) = int_0^x (x - s) kappa(s) ds. For Hermite cubics (C^1) kappa is
!! piecewise linear and discontinuous at the nodes (2 values per element); for cubic
!! B-splines (C^2) it is continuous piecewise linear (N + 1 nodal values). Either way
!! kappa has J coefficients z and the unknowns are U = T z, T the double integration.
!! The energy is 1/2 U^T K U = 1/2 z^T G z with G = EI times the mass matrix of those
!! piecewise linears (bandwidth 1, condition number at most 3 up to scaling), so
!! K = T^-T G T^-1 and
!!
!!     K^-1 f = T G^-1 T^T f,
!!
!! where T^T f is the moment of the loads about each section (sums from the tip), G^-1 a
!! well-conditioned tridiagonal solve (LAPACK dpttrf/dpttrs) and T two cumulative sums
!! from the clamp. Each stage
!! only sums: the relative error on a smooth f is a few eps times the number of elements.
!!
!! T, step by step. Hermite, element e of length h, kappa = kL (1 - xi) + kR xi:
!!   theta_e = theta_(e-1) + h (kL + kR)/2,
!!   w_e = w_(e-1) + h theta_(e-1) + h^2 (kL/3 + kR/6).
!! B-splines (de Boor's derivative formula run backwards, knots t, c_1 = c_2 = 0): with
!! e_i the nodal values of kappa (i = 3..N+3), d_i = d_(i-1) + e_i (t_(i+2) - t_i)/2 and
!! c_i = c_(i-1) + d_i (t_(i+3) - t_i)/3, d_2 = 0.
module vibrobeam_flexibility
   use vibrobeam_kinds, only: dp
   use vibrobeam_lapack, only: dpttrf, dpttrs, poison_failed_solve
   use vibrobeam_model, only: beam_model
   implicit none
   private
   public :: cantilever_flexibility

   !> What applying K^-1 needs: the basis, the steps of T, the factor of G and room for z.
   type :: cantilever_flexibility
      logical :: hermite = .true.
      integer :: unknowns = 0                  !! J
      integer :: elements = 0                  !! N
      real(dp) :: h = 0                        !! element length (Hermite)
      real(dp), allocatable :: first_step(:)   !! B-splines: (t_(i+2) - t_i)/2, i = 3..N+3
      real(dp), allocatable :: second_step(:)  !! B-splines: (t_(i+3) - t_i)/3, i = 3..N+3
      real(dp), allocatable :: curvature_pivots(:)      !! (J) D of G = L D L^T (dpttrf)
      real(dp), allocatable :: curvature_multipliers(:) !! (J-1) L of G = L D L^T (dpttrf)
      real(dp), allocatable :: curvature(:)    !! (J) work space for z
   contains
      procedure :: setup
      procedure :: solve
   end type cantilever_flexibility

contains

   !> Prepare K^-1 for the model (clamped at x = 0). stat /= 0 only if G cannot be
   !! factored (a model with a non-positive element length or EI).
   subroutine setup(self, model, stat, errmsg)
      class(cantilever_flexibility), intent(out) :: self
      type(beam_model), intent(in) :: model
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer :: e, i, m, n
      self%hermite = model%basis == 'hermite'
      self%unknowns = model%unknowns
      self%elements = model%elements
      self%h = model%h
      n = model%unknowns
      ! G: diagonal in curvature_pivots, sub-diagonal in curvature_multipliers, until dpttrf
      allocate (self%curvature_pivots(n), self%curvature_multipliers(max(n - 1, 1)), source=0.0_dp)
      if (self%hermite) then
         ! z = (kL_1, kR_1, ..., kL_N, kR_N): G = EI h/6 [2 1; 1 2] per element
         do e = 1, model%elements
            self%curvature_pivots(2*e - 1:2*e) = model%ei*model%h/3
            self%curvature_multipliers(2*e - 1) = model%ei*model%h/6
         end do
      else
         ! z_m = e_(m+2), the value of kappa at x_(m-1): G = EI times the mass matrix of the
         ! hats B_(i,1) on [t_i, t_(i+2)]
         allocate (self%first_step(n), self%second_step(n))
         associate (t => model%knots)
            do m = 1, n
               i = m + 2
               self%first_step(m) = (t(i + 2) - t(i))/2
               self%second_step(m) = (t(i + 3) - t(i))/3
               self%curvature_pivots(m) = model%ei*(t(i + 2) - t(i))/3
               if (m < n) self%curvature_multipliers(m) = model%ei*(t(i + 2) - t(i + 1))/6
            end do
         end associate
      end if
      errmsg = ''
      call dpttrf(n, self%curvature_pivots, self%curvature_multipliers, stat)
      if (stat /= 0) write (errmsg, '(a,i0,a)') 'curvature mass matrix: dpttrf failed at pivot ', stat, &
         ' (element length and EI must be > 0)'
      allocate (self%curvature(n))
   end subroutine setup

   !> Overwrite x with K^-1 x (x: J generalized forces in, J unknowns out). No allocation.
   subroutine solve(self, x)
      class(cantilever_flexibility), intent(inout) :: self
      real(dp), intent(inout) :: x(:)   !! (J)
      integer :: info
      if (self%unknowns == 0) return
      if (self%hermite) then
         call hermite_moments(self%elements, self%h, x, self%curvature)
      else
         call spline_moments(self%unknowns, self%first_step, self%second_step, x, self%curvature)
      end if
      call dpttrs(self%unknowns, 1, self%curvature_pivots, self%curvature_multipliers, self%curvature, &
                  self%unknowns, info)
      call poison_failed_solve(info, self%curvature)
      if (self%hermite) then
         call hermite_integrate(self%elements, self%h, self%curvature, x)
      else
         call spline_integrate(self%unknowns, self%first_step, self%second_step, self%curvature, x)
      end if
   end subroutine solve

   !> z = T^T f for Hermite elements: from the tip, the shear and the moment of the loads
   !! beyond each element, then the element's share of them.
   pure subroutine hermite_moments(elements, h, f, z)
      integer, intent(in) :: elements
      real(dp), intent(in) :: h, f(2*elements)
      real(dp), intent(out) :: z(2*elements)
      real(dp) :: shear, moment
      integer :: e
      shear = 0
      moment = 0
      do e = elements, 1, -1
         ! (shear, moment) at node e: the loads at node e plus those beyond, carried over h
         moment = f(2*e) + h*shear + moment
         shear = f(2*e - 1) + shear
         z(2*e - 1) = h**2/3*shear + h/2*moment
         z(2*e) = h**2/6*shear + h/2*moment
      end do
   end subroutine hermite_moments

   !> U = T z for Hermite elements: slope and deflection from the clamp.
   pure subroutine hermite_integrate(elements, h, z, u)
      integer, intent(in) :: elements
      real(dp), intent(in) :: h, z(2*elements)
      real(dp), intent(out) :: u(2*elements)
      real(dp) :: deflection, slope
      integer :: e
      deflection = 0
      slope = 0
      do e = 1, elements
         deflection = deflection + h*slope + h**2*(z(2*e - 1)/3 + z(2*e)/6)
         slope = slope + h*(z(2*e - 1) + z(2*e))/2
         u(2*e - 1) = deflection
         u(2*e) = slope
      end do
   end subroutine hermite_integrate

   !> z = T^T f for B-splines: z_m = a_m sum_(k>=m) b_k sum_(i>=k) f_i.
   pure subroutine spline_moments(n, first_step, second_step, f, z)
      integer, intent(in) :: n
      real(dp), intent(in) :: first_step(n), second_step(n), f(n)
      real(dp), intent(out) :: z(n)
      real(dp) :: shear, moment
      integer :: m
      shear = 0
      moment = 0
      do m = n, 1, -1
         shear = shear + f(m)
         moment = moment + second_step(m)*shear
         z(m) = first_step(m)*moment
      end do
   end subroutine spline_moments

   !> c = T z for B-splines: coefficients of the first derivative, then of the spline.
   pure subroutine spline_integrate(n, first_step, second_step, z, c)
      integer, intent(in) :: n
      real(dp), intent(in) :: first_step(n), second_step(n), z(n)
      real(dp), intent(out) :: c(n)
      real(dp) :: slope_coefficient, coefficient
      integer :: m
      slope_coefficient = 0
      coefficient = 0
      do m = 1, n
         slope_coefficient = slope_coefficient + first_step(m)*z(m)
         coefficient = coefficient + second_step(m)*slope_coefficient
         c(m) = coefficient
      end do
   end subroutine spline_integrate
end module vibrobeam_flexibility
