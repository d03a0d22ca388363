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
   use vibrobeam_status, only: stat_invalid_argument
   use vibrobeam_model, only: beam_model, flexibility_applies
   implicit none
   private
   public :: cantilever_flexibility, flexibility_rounding

   !> What applying K^-1 needs: the basis, the steps of T, the factor of G and room for z.
   !! The curvature space (z) is also what `vibrobeam_support_moments` works in: element e
   !! (1..N, from node e-1 to node e) carries kappa linear between z(`curvature_index`(e, 1))
   !! and z(`curvature_index`(e, 2)); G = EI times the mass matrix of these piecewise
   !! linears.
   type :: cantilever_flexibility
      logical :: hermite = .true.
      integer :: unknowns = 0                  !! J
      integer :: elements = 0                  !! N
      real(dp) :: h = 0                        !! element length (Hermite)
      real(dp) :: ei = 0                       !! EI (N m^2)
      real(dp), allocatable :: position(:)     !! (0:N) node positions of the integration T (m)
      real(dp), allocatable :: first_step(:)   !! B-splines: (t_(i+2) - t_i)/2, i = 3..N+3
      real(dp), allocatable :: second_step(:)  !! B-splines: (t_(i+3) - t_i)/3, i = 3..N+3
      real(dp), allocatable :: curvature_pivots(:)      !! (J) D of G = L D L^T (dpttrf)
      real(dp), allocatable :: curvature_multipliers(:) !! (J-1) L of G = L D L^T (dpttrf)
      !> (J), (J-1): the factor of G with its off-diagonal negated, EI (D - O) (G = EI (D + O),
      !! O >= 0): (EI (D - O))^-1 m >= |G^-1| m for every m >= 0 (`magnitude`)
      real(dp), allocatable :: bound_pivots(:), bound_multipliers(:)
      real(dp), allocatable :: curvature(:)    !! (J) work space for z
   contains
      procedure :: setup
      procedure :: solve
      procedure :: curvature_of_loads
      procedure :: displacement_of_curvature
      procedure :: magnitude
      procedure :: curvature_magnitude
      procedure :: curvature_index
   end type cantilever_flexibility

contains

   !> Prepare K^-1 for the model, which must be a uniform beam clamped at x = 0 and free at
   !! x = L, without end springs, intermediate supports or axial force (`flexibility_applies`:
   !! the double integration starts at the clamp). stat = stat_invalid_argument for another
   !! structure; otherwise stat /= 0 only if G cannot be factored (a model with a
   !! non-positive element length or EI).
   subroutine setup(self, model, stat, errmsg)
      class(cantilever_flexibility), intent(out) :: self
      type(beam_model), intent(in) :: model
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer :: e, i, m, n
      if (.not. flexibility_applies(model)) then
         stat = stat_invalid_argument
         errmsg = 'the flexibility by double integration is that of the uniform clamped-free beam, not of a '// &
                  model%boundary%name()//' one with its supports, sections or axial force'
         return
      end if
      self%hermite = model%hermite
      self%unknowns = model%unknowns
      self%elements = model%elements
      self%h = model%h
      self%ei = model%ei
      n = model%unknowns
      ! G: diagonal in curvature_pivots, sub-diagonal in curvature_multipliers, until dpttrf
      allocate (self%curvature_pivots(n), self%curvature_multipliers(max(n - 1, 1)), source=0.0_dp)
      allocate (self%position(0:model%elements))
      if (self%hermite) then
         ! z = (kL_1, kR_1, ..., kL_N, kR_N): G = EI h/6 [2 1; 1 2] per element
         do e = 1, model%elements
            self%curvature_pivots(2*e - 1:2*e) = model%ei*model%h/3
            self%curvature_multipliers(2*e - 1) = model%ei*model%h/6
         end do
         self%position(:) = [(e*model%h, e=0, model%elements)]
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
            ! node e of the mesh is the knot t_(e+4) (four knots at 0)
            self%position(:) = t(4:model%elements + 4)
         end associate
      end if
      self%bound_pivots = self%curvature_pivots
      self%bound_multipliers = -self%curvature_multipliers
      errmsg = ''
      call dpttrf(n, self%curvature_pivots, self%curvature_multipliers, stat)
      if (stat == 0) call dpttrf(n, self%bound_pivots, self%bound_multipliers, stat)
      if (stat /= 0) write (errmsg, '(a,i0,a)') 'curvature mass matrix: dpttrf failed at pivot ', stat, &
         ' (element length and EI must be > 0)'
      allocate (self%curvature(n))
   end subroutine setup

   !> Overwrite x with K^-1 x (x: J generalized forces in, J unknowns out). No allocation.
   subroutine solve(self, x)
      class(cantilever_flexibility), intent(inout) :: self
      real(dp), intent(inout) :: x(:)   !! (J)
      if (self%unknowns == 0) return
      call moments_then_curvature(self, x, self%curvature_pivots, self%curvature_multipliers, self%curvature)
      call integrate(self, self%curvature, x)
   end subroutine solve

   !> z = G^-1 T^T f: the curvature (1/m) of the equilibrium under the loads f, i.e. the
   !! bending moment of f divided by EI, in the curvature space (type documentation).
   subroutine curvature_of_loads(self, f, z)
      class(cantilever_flexibility), intent(in) :: self
      real(dp), intent(in) :: f(:)    !! (J) generalized forces
      real(dp), intent(out) :: z(:)   !! (J) curvature coefficients
      if (self%unknowns == 0) return
      call moments_then_curvature(self, f, self%curvature_pivots, self%curvature_multipliers, z)
   end subroutine curvature_of_loads

   !> U = T z: the unknowns of the displacement whose curvature is z (clamped at x = 0).
   subroutine displacement_of_curvature(self, z, u)
      class(cantilever_flexibility), intent(in) :: self
      real(dp), intent(in) :: z(:)    !! (J)
      real(dp), intent(out) :: u(:)   !! (J)
      if (self%unknowns == 0) return
      call integrate(self, z, u)
   end subroutine displacement_of_curvature

   !> An upper bound of every magnitude the evaluation of K^-1 f goes through, for the
   !! round-off bounds of its callers: given |f| (componentwise), u_bound = T (EI (D - O))^-1
   !! T^T |f|. Every coefficient of T and T^T is >= 0, so T^T |f| bounds every partial sum of
   !! the moments, (EI (D - O))^-1 bounds |G^-1| on non-negative vectors (Neumann series: G =
   !! EI (D + O) with O >= 0 and ||D^-1 O|| <= 1/2), and T of it bounds every partial sum of
   !! the integration. Hence the computed K^-1 f errs by at most (4N + 20) eps u_bound
   !! (`flexibility_rounding`; derivation in docs/method.md, "Statics").
   subroutine magnitude(self, f_abs, u_bound)
      class(cantilever_flexibility), intent(in) :: self
      real(dp), intent(in) :: f_abs(:)     !! (J) |f| (>= 0)
      real(dp), intent(out) :: u_bound(:)  !! (J) >= 0
      real(dp) :: z(self%unknowns)
      if (self%unknowns == 0) return
      call moments_then_curvature(self, f_abs, self%bound_pivots, self%bound_multipliers, z)
      call integrate(self, z, u_bound)
   end subroutine magnitude

   !> The first half of `magnitude`: z_bound = (EI (D - O))^-1 T^T |f| >= |G^-1 T^T f| and
   !! >= every partial result of the curvature of f; flexibility_rounding(N) z_bound bounds
   !! the round-off of `curvature_of_loads`.
   subroutine curvature_magnitude(self, f_abs, z_bound)
      class(cantilever_flexibility), intent(in) :: self
      real(dp), intent(in) :: f_abs(:)     !! (J) |f| (>= 0)
      real(dp), intent(out) :: z_bound(:)  !! (J) >= 0
      if (self%unknowns == 0) return
      call moments_then_curvature(self, f_abs, self%bound_pivots, self%bound_multipliers, z_bound)
   end subroutine curvature_magnitude

   !> The round-off of K^-1 f computed by `solve` (or by `curvature_of_loads` then
   !! `displacement_of_curvature`), relative to `magnitude`: |fl(K^-1 f) - K^-1 f| <=
   !! flexibility_rounding(N) u_bound componentwise. With u = eps/2 and gamma_n = n u/(1 - n u)
   !! (Higham, Accuracy and Stability of Numerical Algorithms, 2002): T^T is at most 3 operations
   !! per element on non-negative coefficients, gamma_(3N+2) times T^T |f|; the tridiagonal
   !! solve with G is backward stable, |dG| <= gamma_4 |L||D||L^T| = gamma_4 G (its multipliers
   !! are positive), which |G^-1| G <= 3 (in the infinity norm, ||D^-1 O|| <= 1/2) turns into
   !! 3 gamma_4 of the curvature bound; T adds gamma_(3N+3) of T|z|. The sum, (6N + 17) u,
   !! is below (4N + 20) eps.
   pure real(dp) function flexibility_rounding(elements)
      integer, intent(in) :: elements
      flexibility_rounding = (4*elements + 20)*epsilon(1.0_dp)
   end function flexibility_rounding

   !> Index in z of the curvature at the left (side = 1) or right (side = 2) end of element e.
   elemental integer function curvature_index(self, e, side)
      class(cantilever_flexibility), intent(in) :: self
      integer, intent(in) :: e, side
      if (self%hermite) then
         curvature_index = 2*e - 2 + side
      else
         curvature_index = e - 1 + side
      end if
   end function curvature_index

   !> z = (factored tridiagonal)^-1 T^T f.
   subroutine moments_then_curvature(self, f, pivots, multipliers, z)
      type(cantilever_flexibility), intent(in) :: self
      real(dp), intent(in) :: f(:), pivots(:), multipliers(:)
      real(dp), intent(out) :: z(:)
      integer :: info
      if (self%hermite) then
         call hermite_moments(self%elements, self%h, f, z)
      else
         call spline_moments(self%unknowns, self%first_step, self%second_step, f, z)
      end if
      call dpttrs(self%unknowns, 1, pivots, multipliers, z, self%unknowns, info)
      call poison_failed_solve(info, z)
   end subroutine moments_then_curvature

   !> u = T z.
   pure subroutine integrate(self, z, u)
      type(cantilever_flexibility), intent(in) :: self
      real(dp), intent(in) :: z(:)
      real(dp), intent(out) :: u(:)
      if (self%hermite) then
         call hermite_integrate(self%elements, self%h, z, u)
      else
         call spline_integrate(self%unknowns, self%first_step, self%second_step, z, u)
      end if
   end subroutine integrate

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
