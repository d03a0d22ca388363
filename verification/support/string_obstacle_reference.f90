!> The exact solution of a string between fixed ends against a rigid point obstacle
!! (docs/theory.md §7, "A string against a point obstacle"), by characteristics, independent
!! of vibrobeam's solver: the reference of verification/dynamics/test_string_obstacle.f90
!! and of studies/string_obstacle.
!!
!! The string (length L, wave speed c, tension T = 1 per unit rho S) is pinned at 0 and L;
!! the obstacle holds u(x0, t) >= level. On each side of x0, u = f(x - ct) + g(x + ct)
!! (d'Alembert). At x0 the incoming waves a(t) (from the left) and b(t) (from the right)
!! are known from the past: a(t) = -(w - a)(t - 2 x0/c) and b(t) = -(w - b)(t - 2(L - x0)/c)
!! once the initial data have passed (the fixed ends reflect with a change of sign); the
!! point's displacement w(t) follows s = a + b while above the obstacle and stays at the
!! level while s decreases (the Skorokhod problem: w' = s' + c R/(2T), R >= 0 the contact
!! force, R (w - level) = 0). The outgoing waves are w - a (to the left) and w - b (to the
!! right). With piecewise-linear initial data (u0 linear, v0 constant between knots) every
!! function is piecewise linear: the solution is built exactly, window by window of the
!! shorter delay, on a list of times (the breakpoints), the instants where the point lands
!! on the obstacle computed in closed form.
module vibrobeam_string_obstacle_reference
   use vibrobeam_kinds, only: dp
   use vibrobeam_sorting, only: sorted
   implicit none
   private

   !> The string, its initial data and the history of the obstacle point.
   type, public :: string_reference
      real(dp) :: length = 1, c = 1, x0 = 0.5_dp, level = 0
      real(dp), allocatable :: knots(:)     !! x of the initial data's knots (0 .. L)
      real(dp), allocatable :: f0(:), g0(:) !! the initial waves f, g at the knots
      integer :: points = 0                 !! history length
      real(dp), allocatable :: t(:), a(:), b(:), w(:)
   contains
      procedure :: build
      procedure :: displacement
      procedure :: energy
      procedure :: initial_energy
      procedure :: in_contact
      procedure :: point_displacement
      procedure :: incoming_at
      procedure :: contact_intervals
   end type string_reference

   public :: new_string_reference

contains

   !> The string with u0 linear between `knots` (values `u0`) and v0 constant on each
   !! interval (`v0`, one fewer), the obstacle u(x0) >= level.
   function new_string_reference(length, c, x0, level, knots, u0, v0) result(ref)
      real(dp), intent(in) :: length, c, x0, level, knots(:), u0(:), v0(:)
      type(string_reference) :: ref
      real(dp) :: p(size(knots))
      integer :: k
      ref%length = length
      ref%c = c
      ref%x0 = x0
      ref%level = level
      allocate (ref%knots, source=knots)
      p(1) = 0
      do k = 2, size(knots)
         p(k) = p(k - 1) + v0(k - 1)*(knots(k) - knots(k - 1))
      end do
      ! u0 = f + g, v0 = c (g' - f')
      allocate (ref%f0, source=0.5_dp*(u0 - p/c))
      allocate (ref%g0, source=0.5_dp*(u0 + p/c))
   end function new_string_reference

   !> Piecewise-linear interpolation of y(:) given at x(:) (increasing), clamped to the ends.
   pure real(dp) function interpolate(x, y, at)
      real(dp), intent(in) :: x(:), y(:), at
      integer :: lo, hi, mid
      if (at <= x(1)) then
         interpolate = y(1)
         return
      end if
      if (at >= x(size(x))) then
         interpolate = y(size(x))
         return
      end if
      lo = 1
      hi = size(x)
      do while (hi - lo > 1)
         mid = (lo + hi)/2
         if (x(mid) <= at) then
            lo = mid
         else
            hi = mid
         end if
      end do
      interpolate = y(lo) + (y(hi) - y(lo))*(at - x(lo))/(x(hi) - x(lo))
   end function interpolate

   !> The incoming waves at the point at time tau (tau within the built history, or within
   !! the first passage of the initial data).
   pure subroutine incoming(self, tau, a, b)
      class(string_reference), intent(in) :: self
      real(dp), intent(in) :: tau
      real(dp), intent(out) :: a, b
      real(dp) :: delay_left, delay_right, s
      delay_left = 2*self%x0/self%c
      delay_right = 2*(self%length - self%x0)/self%c
      if (tau <= delay_left) then
         if (self%c*tau <= self%x0) then
            a = interpolate(self%knots, self%f0, self%x0 - self%c*tau)
         else
            a = -interpolate(self%knots, self%g0, self%c*tau - self%x0)
         end if
      else
         s = tau - delay_left
         a = -(interpolate(self%t(:self%points), self%w(:self%points), s) &
               - interpolate(self%t(:self%points), self%a(:self%points), s))
      end if
      if (tau <= delay_right) then
         if (self%c*tau <= self%length - self%x0) then
            b = interpolate(self%knots, self%g0, self%x0 + self%c*tau)
         else
            b = -interpolate(self%knots, self%f0, 2*self%length - self%x0 - self%c*tau)
         end if
      else
         s = tau - delay_right
         b = -(interpolate(self%t(:self%points), self%w(:self%points), s) &
               - interpolate(self%t(:self%points), self%b(:self%points), s))
      end if
   end subroutine incoming

   !> Append a history point.
   subroutine append(self, tau, a, b, w)
      class(string_reference), intent(inout) :: self
      real(dp), intent(in) :: tau, a, b, w
      integer :: n
      n = self%points
      if (n == size(self%t)) then
         call grow(self%t)
         call grow(self%a)
         call grow(self%b)
         call grow(self%w)
      end if
      n = n + 1
      self%t(n) = tau
      self%a(n) = a
      self%b(n) = b
      self%w(n) = w
      self%points = n
   contains
      !> Double the length of a history array, keeping its values.
      subroutine grow(values)
         real(dp), allocatable, intent(inout) :: values(:)
         real(dp), allocatable :: grown(:)
         allocate (grown(2*size(values)))
         grown(:size(values)) = values
         call move_alloc(grown, values)
      end subroutine grow
   end subroutine append

   !> Build the history up to t_end. Within a window of the shorter delay D the incoming
   !! waves are linear between the candidate times (the knots' passage times and the
   !! history's times shifted by each delay), so w is exact on each piece: in flight it
   !! follows s, until it reaches the level (the landing instant, inserted), and on the
   !! obstacle it stays while s decreases (it leaves where s turns up, a candidate time).
   !! Points where a, b and w are all collinear with their neighbours are dropped so that
   !! the history grows with the kinks, not with the windows.
   subroutine build(self, t_end)
      class(string_reference), intent(inout) :: self
      real(dp), intent(in) :: t_end
      real(dp) :: window, start, finish, a, b, s, s_before, w, slope, landing, merge_gap
      real(dp), allocatable :: times(:)
      integer :: k, first_new
      allocate (self%t(1024), self%a(1024), self%b(1024), self%w(1024))
      self%points = 0
      call incoming(self, 0.0_dp, a, b)
      if (a + b < self%level) error stop 'string_reference: the initial state is inside the obstacle'
      call append(self, 0.0_dp, a, b, a + b)
      window = 2*min(self%x0, self%length - self%x0)/self%c
      merge_gap = 1e-12_dp*self%length/self%c
      start = 0
      do while (start < t_end)
         finish = min(start + window, t_end)
         times = candidates(self, start, finish, merge_gap)
         first_new = self%points + 1
         s_before = self%a(self%points) + self%b(self%points)
         do k = 1, size(times)
            call incoming(self, times(k), a, b)
            s = a + b
            w = self%w(self%points)
            slope = (s - s_before)/(times(k) - self%t(self%points))
            if (w > self%level .or. slope > 0) then
               w = w + (s - s_before)
               if (w < self%level) then
                  ! lands between the two times: the exact instant, where a and b are linear
                  landing = self%t(self%points) + (self%w(self%points) - self%level)/(-slope)
                  if (landing - self%t(self%points) > merge_gap .and. times(k) - landing > merge_gap) then
                     call append(self, landing, &
                                 interpolate([self%t(self%points), times(k)], [self%a(self%points), a], landing), &
                                 interpolate([self%t(self%points), times(k)], [self%b(self%points), b], landing), &
                                 self%level)
                  end if
                  w = self%level
               end if
            end if
            call append(self, times(k), a, b, w)
            s_before = s
         end do
         call drop_collinear(self, first_new)
         start = finish
      end do
   end subroutine build

   !> Sorted times in (start, finish] where a or b may have a kink, closer ones merged.
   function candidates(self, start, finish, merge_gap) result(times)
      class(string_reference), intent(in) :: self
      real(dp), intent(in) :: start, finish, merge_gap
      real(dp), allocatable :: times(:), all(:)
      real(dp) :: delays(2)
      integer :: k, n
      delays = [2*self%x0, 2*(self%length - self%x0)]/self%c
      all = [abs(self%x0 - self%knots)/self%c, (self%x0 + self%knots)/self%c, &
             (2*self%length - self%x0 - self%knots)/self%c, delays/2, delays, &
             self%t(:self%points) + delays(1), self%t(:self%points) + delays(2), finish]
      all = pack(all, all > start + merge_gap .and. all <= finish)
      all = sorted(all)   ! a few hundred values per window
      allocate (times(size(all)))
      n = 0
      do k = 1, size(all)
         if (n > 0) then
            if (all(k) - times(n) <= merge_gap) cycle
         end if
         n = n + 1
         times(n) = all(k)
      end do
      times = times(:n)
      if (times(n) < finish) times = [times, finish]
   end function candidates

   !> Remove the points from `first` on (but the last) at which a, b and w are all
   !! collinear with their neighbours (to 1e-13 of the largest value).
   subroutine drop_collinear(self, first)
      class(string_reference), intent(inout) :: self
      integer, intent(in) :: first
      integer :: k, kept
      real(dp) :: scale
      scale = 1e-13_dp*max(maxval(abs(self%f0)) + maxval(abs(self%g0)), abs(self%level), tiny(1.0_dp))
      kept = first - 1
      do k = first, self%points - 1
         if (kept >= 1) then
            if (off_line(self%a) <= scale .and. off_line(self%b) <= scale .and. off_line(self%w) <= scale) cycle
         end if
         kept = kept + 1
         self%t(kept) = self%t(k)
         self%a(kept) = self%a(k)
         self%b(kept) = self%b(k)
         self%w(kept) = self%w(k)
      end do
      kept = kept + 1
      self%t(kept) = self%t(self%points)
      self%a(kept) = self%a(self%points)
      self%b(kept) = self%b(self%points)
      self%w(kept) = self%w(self%points)
      self%points = kept
   contains
      !> Distance of y(k) from the line through the last kept point and y(k + 1).
      real(dp) function off_line(y)
         real(dp), intent(in) :: y(:)
         off_line = abs(y(k) - (y(kept) + (y(k + 1) - y(kept))*(self%t(k) - self%t(kept))/(self%t(k + 1) - self%t(kept))))
      end function off_line
   end subroutine drop_collinear

   !> The outgoing wave to the left (w - a) or right (w - b) emitted at time tau.
   pure real(dp) function outgoing(self, tau, left)
      class(string_reference), intent(in) :: self
      real(dp), intent(in) :: tau
      logical, intent(in) :: left
      real(dp) :: w
      w = interpolate(self%t(:self%points), self%w(:self%points), tau)
      if (left) then
         outgoing = w - interpolate(self%t(:self%points), self%a(:self%points), tau)
      else
         outgoing = w - interpolate(self%t(:self%points), self%b(:self%points), tau)
      end if
   end function outgoing

   !> u(x, t), t within the built history.
   pure real(dp) function displacement(self, x, time)
      class(string_reference), intent(in) :: self
      real(dp), intent(in) :: x, time
      displacement = right_moving(self, x - self%c*time, x <= self%x0) + left_moving(self, x + self%c*time, x <= self%x0)
   end function displacement

   !> f at xi on the left (left = .true.) or right side of the point.
   pure recursive real(dp) function right_moving(self, xi, left) result(value)
      class(string_reference), intent(in) :: self
      real(dp), intent(in) :: xi
      logical, intent(in) :: left
      if (left) then
         if (xi >= 0) then
            value = interpolate(self%knots, self%f0, xi)
         else
            value = -left_moving(self, -xi, .true.)
         end if
      else
         if (xi >= self%x0) then
            value = interpolate(self%knots, self%f0, xi)
         else
            value = outgoing(self, (self%x0 - xi)/self%c, .false.)
         end if
      end if
   end function right_moving

   !> g at xi on the left or right side of the point.
   pure recursive real(dp) function left_moving(self, xi, left) result(value)
      class(string_reference), intent(in) :: self
      real(dp), intent(in) :: xi
      logical, intent(in) :: left
      if (left) then
         if (xi <= self%x0) then
            value = interpolate(self%knots, self%g0, xi)
         else
            value = outgoing(self, (xi - self%x0)/self%c, .true.)
         end if
      else
         if (xi <= self%length) then
            value = interpolate(self%knots, self%g0, xi)
         else
            value = -right_moving(self, 2*self%length - xi, .false.)
         end if
      end if
   end function left_moving

   !> The initial energy per unit rho S, 1/2 int (v0^2 + c^2 u0'^2) = c^2 int (f'^2 + g'^2).
   pure real(dp) function initial_energy(self)
      class(string_reference), intent(in) :: self
      integer :: k
      real(dp) :: dx
      initial_energy = 0
      do k = 1, size(self%knots) - 1
         dx = self%knots(k + 1) - self%knots(k)
         initial_energy = initial_energy + self%c**2*((self%f0(k + 1) - self%f0(k))**2 + (self%g0(k + 1) - self%g0(k))**2)/dx
      end do
   end function initial_energy

   !> The energy per unit rho S at time t >= 2 max(x0, L - x0)/c, from the waves the point
   !! emitted: each side holds what it emitted in the last 2 x0/c (left) or 2(L - x0)/c
   !! (right), c int (d outgoing/d tau)^2 d tau.
   pure real(dp) function energy(self, time)
      class(string_reference), intent(in) :: self
      real(dp), intent(in) :: time
      energy = self%c*(emitted(self%t(:self%points), self%w(:self%points) - self%a(:self%points), &
                               time - 2*self%x0/self%c, time) &
                       + emitted(self%t(:self%points), self%w(:self%points) - self%b(:self%points), &
                                 time - 2*(self%length - self%x0)/self%c, time))
   end function energy

   !> int_from^to y'^2 for y piecewise linear on x.
   pure real(dp) function emitted(x, y, from, to)
      real(dp), intent(in) :: x(:), y(:), from, to
      integer :: k
      real(dp) :: overlap
      emitted = 0
      do k = 1, size(x) - 1
         overlap = min(x(k + 1), to) - max(x(k), from)
         if (overlap > 0) emitted = emitted + ((y(k + 1) - y(k))/(x(k + 1) - x(k)))**2*overlap
      end do
   end function emitted

   !> Whether the point is on the obstacle at time t (within 1e-13 of the amplitudes).
   pure logical function in_contact(self, time)
      class(string_reference), intent(in) :: self
      real(dp), intent(in) :: time
      in_contact = interpolate(self%t(:self%points), self%w(:self%points), time) - self%level <= &
                   1e-13_dp*(maxval(abs(self%f0)) + maxval(abs(self%g0)))
   end function in_contact

   !> w(t), the displacement of the obstacle point, t within the built history.
   pure real(dp) function point_displacement(self, time)
      class(string_reference), intent(in) :: self
      real(dp), intent(in) :: time
      point_displacement = interpolate(self%t(:self%points), self%w(:self%points), time)
   end function point_displacement

   !> The incoming waves a(t), b(t) at the point, t within the built history.
   pure subroutine incoming_at(self, time, a, b)
      class(string_reference), intent(in) :: self
      real(dp), intent(in) :: time
      real(dp), intent(out) :: a, b
      a = interpolate(self%t(:self%points), self%a(:self%points), time)
      b = interpolate(self%t(:self%points), self%b(:self%points), time)
   end subroutine incoming_at

   !> The contact intervals of the built history: the point lands at starts(k) and leaves
   !! at ends(k) (the end of the history if it is still on the obstacle there). With
   !! `pressed`, only where the obstacle pushes (R > 0: the point rests while the arriving
   !! waves' sum s decreases); a point can also rest on the obstacle with R = 0, where s
   !! stays constant.
   pure subroutine contact_intervals(self, starts, ends, pressed)
      class(string_reference), intent(in) :: self
      real(dp), allocatable, intent(out) :: starts(:), ends(:)
      logical, intent(in), optional :: pressed
      logical :: on(self%points - 1)
      integer :: n
      n = self%points
      ! piece k is [t(k), t(k + 1)]
      on = self%w(:n - 1) <= self%level .and. self%w(2:n) <= self%level
      if (present(pressed)) then
         if (pressed) on = on .and. self%a(2:n) + self%b(2:n) < self%a(:n - 1) + self%b(:n - 1)
      end if
      starts = pack(self%t(:n - 1), on .and. .not. eoshift(on, -1, .false.))
      ends = pack(self%t(2:n), on .and. .not. eoshift(on, 1, .false.))
   end subroutine contact_intervals
end module vibrobeam_string_obstacle_reference
