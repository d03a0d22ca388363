!> The supports at the beam's ends (theory §1, "Supports"): which degrees of freedom they
!! hold, the springs that act there, and what the code that needs a property of the
!! supported beam must ask instead of assuming a clamped-free beam (the closed-form
!! frequencies and mode shapes, the end where modes are normalized, how many rigid-body
!! motions the ends leave free).
!!
!! Each end is clamped (deflection and rotation held), pinned (deflection held), sliding
!! (rotation held, deflection free) or free, and may carry a translational spring (force
!! -k u) and a rotational spring (moment -k_r u_x), whatever its support. Held degrees of
!! freedom carry no unknown: in the basis of the mesh (`vibrobeam_model`) the Hermite
!! unknowns of node i are (w_i, theta_i), i = 0..N, and a held one is removed; the cubic
!! B-spline coefficients c_1..c_{N+3} give u(0) = c_1, u'(0) = 3 (c_2 - c_1)/h,
!! u(L) = c_{N+3} and u'(L) = 3 (c_{N+3} - c_{N+2})/h, so a held deflection removes c_1
!! (c_{N+3}), a clamp also c_2 (c_{N+2}), and a sliding end ties c_2 to c_1 (c_{N+2} to
!! c_{N+3}): the two coefficients become one unknown, whose function is B_1 + B_2, the
!! change of basis of docs/method.md ("Supports"); `vibrobeam_model` builds it.
module vibrobeam_boundary
   use vibrobeam_kinds, only: dp
   use vibrobeam_cantilever_exact, only: cantilever_frequency, cantilever_mode_shape, cantilever_root, &
      pinned_tip_root, clamped_clamped_root, clamped_sliding_root
   implicit none
   private
   public :: boundary_conditions, end_clamped, end_pinned, end_sliding, end_free, end_names, end_code

   integer, parameter :: end_clamped = 1, end_pinned = 2, end_sliding = 3, end_free = 4
   character(len=*), parameter :: end_names = 'clamped|pinned|sliding|free'

   !> The supports of the two ends; today's beam, clamped at x = 0 and free at x = L, by default.
   type :: boundary_conditions
      integer :: left = end_clamped
      integer :: right = end_free
      !> end springs: translational (N/m) and rotational (N m/rad), per unit rho S when the
      !! beam is given by k2 (like every force)
      real(dp) :: left_spring = 0, left_rotational_spring = 0
      real(dp) :: right_spring = 0, right_rotational_spring = 0
   contains
      procedure :: is_clamped_free      !! the cantilever ends, without springs
      procedure :: has_springs          !! any end spring?
      procedure :: name                 !! 'clamped-free', ...
      procedure :: end_name             !! 'clamped', ... of the left (1) or right (2) end
      procedure :: holds_deflection     !! is the deflection held at the left (1) or right (2) end?
      procedure :: holds_rotation       !! is the rotation held at the left (1) or right (2) end?
      procedure :: has_closed_form      !! are natural_frequency's values known in closed form?
      procedure :: has_mode_shapes      !! is mode_shape known in closed form?
      procedure :: rigid_motions        !! rigid-body motions the ends leave free (0, 1 or 2)
      procedure :: held_count           !! degrees of freedom the ends hold (0..4)
      procedure :: natural_frequency    !! closed form of mode n, where there is one
      procedure :: mode_shape           !! closed form of mode n at x, where there is one
      procedure :: normalization_node   !! the node at which mode shapes are scaled to 1
   end type boundary_conditions

contains

   !> The code of an end support named as in the input ('clamped', ...); 0 for another name.
   pure integer function end_code(text)
      character(len=*), intent(in) :: text
      select case (trim(text))
      case ('clamped')
         end_code = end_clamped
      case ('pinned')
         end_code = end_pinned
      case ('sliding')
         end_code = end_sliding
      case ('free')
         end_code = end_free
      case default
         end_code = 0
      end select
   end function end_code

   pure logical function is_clamped_free(self)
      class(boundary_conditions), intent(in) :: self
      is_clamped_free = self%left == end_clamped .and. self%right == end_free .and. .not. self%has_springs()
   end function is_clamped_free

   pure logical function has_springs(self)
      class(boundary_conditions), intent(in) :: self
      has_springs = self%left_spring > 0 .or. self%left_rotational_spring > 0 .or. self%right_spring > 0 .or. &
                    self%right_rotational_spring > 0
   end function has_springs

   !> 'clamped-free', 'pinned-pinned', ... (left end first), with '+springs' when any acts.
   pure function name(self) result(text)
      class(boundary_conditions), intent(in) :: self
      character(len=:), allocatable :: text
      text = self%end_name(1)//'-'//self%end_name(2)
      if (self%has_springs()) text = text//' (with end springs)'
   end function name

   !> The support of end `side` (1: x = 0, 2: x = L) as the input names it.
   pure function end_name(self, side) result(text)
      class(boundary_conditions), intent(in) :: self
      integer, intent(in) :: side
      character(len=:), allocatable :: text
      select case (merge(self%left, self%right, side == 1))
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

   !> Is the deflection held at end `side` (1: x = 0, 2: x = L)?
   pure logical function holds_deflection(self, side)
      class(boundary_conditions), intent(in) :: self
      integer, intent(in) :: side
      holds_deflection = any(merge(self%left, self%right, side == 1) == [end_clamped, end_pinned])
   end function holds_deflection

   !> Is the rotation held at end `side` (1: x = 0, 2: x = L)?
   pure logical function holds_rotation(self, side)
      class(boundary_conditions), intent(in) :: self
      integer, intent(in) :: side
      holds_rotation = any(merge(self%left, self%right, side == 1) == [end_clamped, end_sliding])
   end function holds_rotation

   !> Are the natural frequencies of the uniform continuum on these supports known in
   !! closed form (theory §7)? For every pair of clamped, pinned, sliding and free ends
   !! without springs; with end springs the caller computes the modes.
   pure logical function has_closed_form(self)
      class(boundary_conditions), intent(in) :: self
      has_closed_form = .not. self%has_springs()
   end function has_closed_form

   !> Are the mode shapes known in closed form (`mode_shape`)? The clamped-free beam only.
   pure logical function has_mode_shapes(self)
      class(boundary_conditions), intent(in) :: self
      has_mode_shapes = self%is_clamped_free()
   end function has_mode_shapes

   !> How many independent rigid-body motions u = a + b x the ends leave free (theory §1,
   !! "Supports"): the rigid motions form a plane, each held deflection or translational
   !! spring at an end removes the combination u(end), each held rotation or rotational
   !! spring removes b; the rank of these conditions is subtracted from 2.
   pure integer function rigid_motions(self)
      class(boundary_conditions), intent(in) :: self
      logical :: value_left, value_right, slope
      value_left = self%holds_deflection(1) .or. self%left_spring > 0
      value_right = self%holds_deflection(2) .or. self%right_spring > 0
      slope = self%holds_rotation(1) .or. self%holds_rotation(2) .or. self%left_rotational_spring > 0 .or. &
              self%right_rotational_spring > 0
      ! u(0) = a, u(L) = a + b L, u' = b: two distinct conditions remove both
      rigid_motions = 2 - min(2, count([value_left, value_right, slope]))
   end function rigid_motions

   !> How many conditions the ends impose on the displacement (a held deflection or rotation
   !! each): the unknowns of the mesh are its degrees of freedom less these, in both bases
   !! (a B-spline sliding end ties two coefficients into one unknown).
   pure integer function held_count(self)
      class(boundary_conditions), intent(in) :: self
      held_count = count([self%holds_deflection(1), self%holds_rotation(1), self%holds_deflection(2), &
                          self%holds_rotation(2)])
   end function held_count

   !> omega_n (rad/s) of the uniform continuum with these supports, k2 = EI/(rho S): 0 for
   !! the rigid-body motions (the first `rigid_motions` modes), then (b_m)^2 sqrt(k2)/L^2
   !! with b_m the m-th root of the pair's frequency equation (module vibrobeam_cantilever_exact).
   !! 0 without a closed form (`has_closed_form`).
   pure real(dp) function natural_frequency(self, n, length, k2)
      class(boundary_conditions), intent(in) :: self
      integer, intent(in) :: n
      real(dp), intent(in) :: length, k2
      real(dp), parameter :: pi = acos(-1.0_dp)
      real(dp) :: b
      integer :: m, low, high
      natural_frequency = 0
      if (.not. self%has_closed_form()) return
      if (self%is_clamped_free()) then
         natural_frequency = cantilever_frequency(n, length, k2)
         return
      end if
      m = n - self%rigid_motions()
      if (m < 1) return
      low = min(self%left, self%right)
      high = max(self%left, self%right)
      ! pairs in the order clamped < pinned < sliding < free
      if (low == end_clamped .and. high == end_free) then
         b = cantilever_root(m)
      else if ((low == end_clamped .and. high == end_clamped) .or. (low == end_free .and. high == end_free)) then
         b = clamped_clamped_root(m)
      else if ((low == end_pinned .and. high == end_pinned) .or. (low == end_sliding .and. high == end_sliding)) then
         b = m*pi
      else if ((low == end_clamped .and. high == end_pinned) .or. (low == end_pinned .and. high == end_free)) then
         b = pinned_tip_root(m)
      else if ((low == end_clamped .and. high == end_sliding) .or. (low == end_sliding .and. high == end_free)) then
         b = clamped_sliding_root(m)
      else   ! pinned-sliding
         b = (m - 0.5_dp)*pi
      end if
      natural_frequency = b**2*sqrt(k2)/length**2
   end function natural_frequency

   !> Mode n of the continuum with these supports at x (derivative of order `order`),
   !! scaled to 1 at its normalization end; 0 without a closed form (`has_mode_shapes`).
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
