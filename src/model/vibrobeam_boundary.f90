!> The supports at the beam's ends (theory §1): which degrees of freedom they hold, and
!! what the code that needs a property of the supported beam must ask instead of assuming
!! a clamped-free beam (the closed-form frequencies and mode shapes, the end where modes
!! are normalized, whether the flexibility fast path applies).
!!
!! Each end is clamped (deflection and rotation held), pinned (deflection held), sliding
!! (rotation held) or free. Held degrees of freedom carry no unknown: in the basis of the
!! mesh (`vibrobeam_model`) the Hermite unknowns of node i are (w_i, theta_i), i = 0..N,
!! and a held one is removed; the cubic B-spline coefficients c_1..c_{N+3} give
!! u(0) = c_1, u'(0) proportional to c_2 - c_1, u(L) = c_{N+3} and u'(L) proportional to
!! c_{N+3} - c_{N+2}, so a held deflection removes c_1 (c_{N+3}) and a clamp also c_2
!! (c_{N+2}). A sliding end of B-splines ties c_2 to c_1, which no removal expresses: it is
!! refused (`basis_dof_held` returns ok = .false.).
module vibrobeam_boundary
   use vibrobeam_kinds, only: dp
   use vibrobeam_cantilever_exact, only: cantilever_frequency, cantilever_mode_shape
   implicit none
   private
   public :: boundary_conditions, end_clamped, end_pinned, end_sliding, end_free, end_names

   integer, parameter :: end_clamped = 1, end_pinned = 2, end_sliding = 3, end_free = 4
   character(len=*), parameter :: end_names = 'clamped|pinned|sliding|free'

   !> The supports of the two ends; today's beam, clamped at x = 0 and free at x = L, by default.
   type :: boundary_conditions
      integer :: left = end_clamped
      integer :: right = end_free
   contains
      procedure :: is_clamped_free      !! the cantilever, for which closed forms and fast paths exist
      procedure :: name                 !! 'clamped-free', ...
      procedure :: basis_dof_held       !! which degrees of freedom of the mesh's basis are held
      procedure :: has_closed_form      !! are natural_frequency and mode_shape known?
      procedure :: natural_frequency    !! closed form of mode n, where there is one
      procedure :: mode_shape           !! closed form of mode n at x, where there is one
      procedure :: normalization_node   !! the node at which mode shapes are scaled to 1
   end type boundary_conditions

contains

   pure logical function is_clamped_free(self)
      class(boundary_conditions), intent(in) :: self
      is_clamped_free = self%left == end_clamped .and. self%right == end_free
   end function is_clamped_free

   !> 'clamped-free', 'pinned-pinned', ... (left end first).
   pure function name(self) result(text)
      class(boundary_conditions), intent(in) :: self
      character(len=:), allocatable :: text
      text = end_name(self%left)//'-'//end_name(self%right)
   end function name

   pure function end_name(code) result(text)
      integer, intent(in) :: code
      character(len=:), allocatable :: text
      select case (code)
      case (end_clamped)
         text = 'clamped'
      case (end_pinned)
         text = 'pinned'
      case (end_sliding)
         text = 'sliding'
      case default
         text = 'free'
      end select
   end function end_name

   !> held(k): basis degree of freedom k is held by a support, for a mesh of `elements`
   !! elements of the basis (`hermite`: 2(N + 1) nodal values and slopes; otherwise the
   !! N + 3 B-spline coefficients). ok = .false. when the basis cannot express a support
   !! by removing degrees of freedom (a sliding end of B-splines).
   pure subroutine basis_dof_held(self, hermite, elements, held, ok)
      class(boundary_conditions), intent(in) :: self
      logical, intent(in) :: hermite
      integer, intent(in) :: elements
      logical, allocatable, intent(out) :: held(:)
      logical, intent(out) :: ok
      integer :: n
      ok = .true.
      if (hermite) then
         n = 2*(elements + 1)
         allocate (held(n), source=.false.)
         held(1) = any(self%left == [end_clamped, end_pinned])
         held(2) = any(self%left == [end_clamped, end_sliding])
         held(n - 1) = any(self%right == [end_clamped, end_pinned])
         held(n) = any(self%right == [end_clamped, end_sliding])
      else
         n = elements + 3
         allocate (held(n), source=.false.)
         held(1) = any(self%left == [end_clamped, end_pinned])
         held(2) = self%left == end_clamped
         held(n) = any(self%right == [end_clamped, end_pinned])
         held(n - 1) = self%right == end_clamped
         ok = self%left /= end_sliding .and. self%right /= end_sliding
      end if
   end subroutine basis_dof_held

   !> Are the natural frequencies and mode shapes of the continuum with these supports
   !! known in closed form (theory §7)? Otherwise the caller computes the modes.
   pure logical function has_closed_form(self)
      class(boundary_conditions), intent(in) :: self
      has_closed_form = self%is_clamped_free()
   end function has_closed_form

   !> omega_n (rad/s) of the continuum with these supports, k2 = EI/(rho S); 0 without a
   !! closed form (`has_closed_form`).
   pure real(dp) function natural_frequency(self, n, length, k2)
      class(boundary_conditions), intent(in) :: self
      integer, intent(in) :: n
      real(dp), intent(in) :: length, k2
      natural_frequency = 0
      if (self%is_clamped_free()) natural_frequency = cantilever_frequency(n, length, k2)
   end function natural_frequency

   !> Mode n of the continuum with these supports at x (derivative of order `order`),
   !! scaled to 1 at its normalization end; 0 without a closed form (`has_closed_form`).
   pure real(dp) function mode_shape(self, n, x, length, order)
      class(boundary_conditions), intent(in) :: self
      integer, intent(in) :: n, order
      real(dp), intent(in) :: x, length
      mode_shape = 0
      if (self%is_clamped_free()) mode_shape = cantilever_mode_shape(n, x, length, order)
   end function mode_shape

   !> The node (0..N) at which mode shapes are scaled to 1: a free end when there is one
   !! (the right end first); -1 when neither end is free: the node of largest magnitude.
   pure integer function normalization_node(self, elements)
      class(boundary_conditions), intent(in) :: self
      integer, intent(in) :: elements
      if (self%right == end_free) then
         normalization_node = elements
      else if (self%left == end_free) then
         normalization_node = 0
      else
         normalization_node = -1
      end if
   end function normalization_node
end module vibrobeam_boundary
