!> The obstacles (&obstacles, docs/input.md): each a flat or sloped surface below or above
!! the beam over [x_from, x_to], rigid or compliant, every variable declared once in
!! `visit_obstacles` (`vibrobeam_schema_visitor`); and how they become the discrete
!! constraints of the mesh (theory §2, "Discrete constraints" K_h, `build_contact_points`).
!!
!! A node that an obstacle covers becomes a contact point c with bounds
!! lower(c) <= u_h(x_c) <= upper(c). Only covered nodes become contact points: a scene with
!! one obstacle at the tip has one contact point. Rules (also in docs/input.md):
!! - punctual obstacle (x_from = x_to): acts at the nearest node; a warning says so when the
!!   obstacle is not on a node (further than 1e-9 h);
!! - longitudinal obstacle: acts at every node in [x_from, x_to] (1e-9 h tolerance), its
!!   level interpolated linearly; one covering no node acts at the node nearest its middle,
!!   with a warning;
!! - several obstacles on the same side of a node: the most restrictive one counts;
!! - a node whose deflection a support holds (the clamped node x = 0 of a cantilever, a
!!   pinned end, docs/input.md "&beam") never moves: an obstacle there is only checked
!!   (u = 0 must be admissible); every other node, the ends included, may become a contact
!!   point;
!! - a compliant obstacle (stiffness > 0, docs/theory.md section 8) gives each node it
!!   covers a spring instead of a bound: its stiffness per unit length is lumped at the
!!   nodes with their tributary lengths inside [x_from, x_to] (h inside, h/2 at an end
!!   node; a punctual one puts its whole stiffness on its node). Springs on the same node
!!   and side act in parallel, each from its own level, and a rigid bound on the same node
!!   and side acts beside them (whichever is reached first holds).
module vibrobeam_obstacles
   use vibrobeam_kinds, only: dp
   use vibrobeam_text, only: real_text, integer_text
   use vibrobeam_schema_visitor, only: schema_visitor, real_row, integer_row, keyword_row, keyword_length
   use vibrobeam_model, only: beam_model, node_row
   use vibrobeam_compliant_law, only: spring_set
   use vibrobeam_contact_set, only: contact_set, no_bound
   implicit none
   private
   public :: obstacle_type, max_obstacles, visit_obstacles, build_contact_points

   integer, parameter :: max_obstacles = 32       !! most obstacles a scene may hold

   !> One obstacle of `&obstacles` (docs/input.md).
   type :: obstacle_type
      character(len=keyword_length) :: side = 'below'   !! 'below' (bounds u from below) | 'above'
      real(dp) :: x_from = 0, x_to = 0      !! extent along the beam (m)
      real(dp) :: level_from = 0, level_to = 0   !! surface height at x_from, x_to (m)
      !> 0: rigid (Newton's law, &impact); > 0: compliant stop with force stiffness p^exponent
      !! (N/m for a punctual obstacle, N/m per m of length for a longitudinal one; per unit
      !! rho S when the beam is given by k2), docs/theory.md section 8
      real(dp) :: stiffness = 0
      real(dp) :: exponent = 1                   !! 1 linear, 1.5 Hertz-like
      real(dp) :: damping = 0                    !! Hunt-Crossley alpha (s/m), compliant stops only
   end type obstacle_type

contains

   !> Every variable of &obstacles, once: `count`, then each obstacle's variables (element
   !! i of each array variable is obstacle i). The rows describe the variables even when
   !! there is no obstacle (element 0). The defaults that follow other inputs (x_from = L,
   !! x_to = x_from, level_to = level_from) and the variables required of each obstacle
   !! are the scene reader's.
   subroutine visit_obstacles(obstacles, count, visitor)
      type(obstacle_type), intent(inout) :: obstacles(:)
      integer, intent(inout) :: count            !! the obstacles given (size(obstacles) once read)
      class(schema_visitor), intent(inout) :: visitor
      type(obstacle_type) :: description
      integer :: i
      call visitor%variable(integer_row('obstacles', 'count', 0, max_obstacles, 'number of obstacles'), count)
      do i = 1, size(obstacles)
         call visit_one(obstacles(i), i)
      end do
      if (size(obstacles) == 0) call visit_one(description, 0)
   contains
      subroutine visit_one(o, i)
         type(obstacle_type), intent(inout) :: o
         integer, intent(in) :: i                  !! the obstacle (0: a description only)
         integer, parameter :: n = max_obstacles
         call visitor%variable(keyword_row('obstacles', 'side', 'below|above', keyword_length, &
                                           'below: bounds u from below (g1); above: from above (g2)', n, i), o%side)
         call visitor%variable(real_row('obstacles', 'x_from', 'm', 0.0_dp, 1e6_dp, &
                                        'start of the obstacle along the beam', n, i), o%x_from)
         call visitor%variable(real_row('obstacles', 'x_to', 'm', 0.0_dp, 1e6_dp, &
                                        'end of the obstacle (x_from: a punctual obstacle)', n, i), o%x_to)
         call visitor%variable(real_row('obstacles', 'level_from', 'm', -1e6_dp, 1e6_dp, &
                                        'height of the obstacle surface at x_from', n, i), o%level_from)
         call visitor%variable(real_row('obstacles', 'level_to', 'm', -1e6_dp, 1e6_dp, &
                                        'height of the obstacle surface at x_to (linear in between)', n, i), o%level_to)
         call visitor%variable(real_row('obstacles', 'stiffness', 'N/m', 0.0_dp, 1e30_dp, &
                                        '0: a rigid stop; > 0: a compliant stop of force stiffness p^exponent', n, i), &
                               o%stiffness)
         call visitor%variable(real_row('obstacles', 'exponent', '', 1.0_dp, 3.0_dp, &
                                        'exponent of the compliant stop''s force (1 linear, 1.5 Hertz-like)', n, i), &
                               o%exponent)
         call visitor%variable(real_row('obstacles', 'damping', 's/m', 0.0_dp, 1e6_dp, &
                                        'Hunt-Crossley contact damping of a compliant stop', n, i), o%damping)
      end subroutine visit_one
   end subroutine visit_obstacles

   !> Build the contact points of the obstacles on `model`'s mesh. Warnings (one line each) are
   !! appended to `warnings`; stat = 1 with a message when the obstacles contradict each
   !! other (a 'below' level at or above an 'above' level) or the clamp.
   subroutine build_contact_points(obstacles, model, contacts, warnings, stat, errmsg)
      type(obstacle_type), intent(in) :: obstacles(:)
      type(beam_model), intent(in) :: model
      type(contact_set), intent(out) :: contacts
      character(len=:), allocatable, intent(inout) :: warnings
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      real(dp) :: lower(0:model%elements), upper(0:model%elements), level, tolerance, xi
      integer :: lower_source(0:model%elements), upper_source(0:model%elements)
      integer :: i, k, first, last, c, j
      logical :: covered(0:model%elements)
      integer :: spring_node(size(obstacles)*(model%elements + 1)), spring_obstacle(size(spring_node))
      real(dp) :: spring_level(size(spring_node)), spring_length(size(spring_node))
      character(len=160) :: line
      stat = 0
      errmsg = ''
      lower = -no_bound
      upper = no_bound
      lower_source = 0
      upper_source = 0
      covered = .false.
      j = 0
      tolerance = 1e-9_dp*model%h
      do k = 1, size(obstacles)
         associate (o => obstacles(k))
            if (o%x_to - o%x_from <= tolerance) then
               first = nint(o%x_from/model%h)
               last = first
               if (abs(model%x(first + 1) - o%x_from) > tolerance) then
                  write (line, '(a,i0,a,g0.6,a,g0.6,a)') 'obstacle ', k, ' at x = ', o%x_from, &
                     ' m is not on a node; it acts at the nearest node x = ', model%x(first + 1), ' m'
                  warnings = warnings//trim(line)//new_line('a')
               end if
            else
               first = ceiling((o%x_from - tolerance)/model%h)
               last = floor((o%x_to + tolerance)/model%h)
               if (last < first) then
                  first = nint(0.5_dp*(o%x_from + o%x_to)/model%h)
                  last = first
                  write (line, '(a,i0,a,g0.6,a)') 'obstacle ', k, ' covers no node; it acts at the node x = ', &
                     model%x(first + 1), ' m nearest its middle'
                  warnings = warnings//trim(line)//new_line('a')
               end if
            end if
            do i = first, last
               if (o%x_to - o%x_from <= tolerance) then
                  level = o%level_from
               else
                  xi = min(1.0_dp, max(0.0_dp, (model%x(i + 1) - o%x_from)/(o%x_to - o%x_from)))
                  level = (1 - xi)*o%level_from + xi*o%level_to
               end if
               if (o%stiffness > 0) then
                  ! a spring, never a bound; a held node never moves and gets none
                  if (model%deflection_held(i)) cycle
                  covered(i) = .true.
                  j = j + 1
                  spring_node(j) = i
                  spring_obstacle(j) = k
                  spring_level(j) = level
                  if (first == last) then
                     spring_length(j) = max(o%x_to - o%x_from, 0.0_dp)
                     if (spring_length(j) <= tolerance) spring_length(j) = 1   ! punctual: the stiffness itself
                  else
                     ! tributary length of node i inside [x_from, x_to]
                     spring_length(j) = max(0.0_dp, min(o%x_to, model%x(i + 1) + 0.5_dp*model%h, model%length) - &
                                        max(o%x_from, model%x(i + 1) - 0.5_dp*model%h))
                  end if
                  cycle
               end if
               if (o%side == 'below') then
                  if (level > lower(i)) then
                     lower(i) = level
                     lower_source(i) = k
                  end if
               else
                  if (level < upper(i)) then
                     upper(i) = level
                     upper_source(i) = k
                  end if
               end if
            end do
         end associate
      end do
      do i = 0, model%elements
         if (.not. model%deflection_held(i)) cycle
         if (lower(i) > 0 .or. upper(i) < 0) then
            if (i == 0 .and. model%boundary%holds_rotation(1)) then
               write (errmsg, '(a,i0,a)') '&obstacles: obstacle ', max(lower_source(0), upper_source(0)), &
                  ' cuts the clamped end x = 0, where u = 0 always; move x_from away from 0 or its level past 0'
            else
               errmsg = '&obstacles: obstacle '//integer_text(max(lower_source(i), upper_source(i)))//' (level '// &
                        real_text(merge(lower(i), upper(i), lower(i) > 0))//' m there) cuts the support at x = '// &
                        real_text(model%x(i + 1))//' m, where u = 0 always; move it away from the support or its '// &
                        'level past 0'
            end if
            stat = 1
            return
         end if
         ! the support holds u = 0 there: the obstacle has nothing left to act on
         lower(i) = -no_bound
         upper(i) = no_bound
         covered(i) = .false.
      end do
      do i = 0, model%elements
         if (lower(i) >= upper(i)) then
            write (errmsg, '(a,i0,a,g0.6,a,i0,a,g0.6,a,g0.6,a)') '&obstacles: the ''below'' obstacle ', &
               lower_source(i), ' (level ', lower(i), ' m) is not under the ''above'' obstacle ', &
               upper_source(i), ' (level ', upper(i), ' m) at x = ', model%x(i + 1), &
               ' m; a below level must be smaller than an above level'
            stat = 1
            return
         end if
      end do
      contacts%count = count(lower > -no_bound .or. upper < no_bound .or. covered)
      allocate (contacts%node(contacts%count), contacts%x(contacts%count), contacts%lower(contacts%count), &
                contacts%upper(contacts%count), contacts%dofs(4, contacts%count), &
                contacts%weights(4, contacts%count), contacts%lower_obstacle(contacts%count), &
                contacts%upper_obstacle(contacts%count))
      c = 0
      do i = 0, model%elements
         if (lower(i) <= -no_bound .and. upper(i) >= no_bound .and. .not. covered(i)) cycle
         c = c + 1
         contacts%node(c) = i
         contacts%x(c) = model%x(i + 1)
         contacts%lower(c) = lower(i)
         contacts%upper(c) = upper(i)
         contacts%lower_obstacle(c) = lower_source(i)
         contacts%upper_obstacle(c) = upper_source(i)
         call node_row(model, i, contacts%dofs(:, c), contacts%weights(:, c))
      end do
      associate (springs => contacts%springs)
         springs%count = j
         allocate (springs%point(j), springs%sign(j), springs%level(j), springs%stiffness(j), &
                   springs%exponent(j), springs%damping(j))
         do k = 1, j
            springs%point(k) = findloc(contacts%node, spring_node(k), 1)
            associate (o => obstacles(spring_obstacle(k)))
               springs%sign(k) = merge(1.0_dp, -1.0_dp, o%side == 'below')
               springs%level(k) = spring_level(k)
               springs%stiffness(k) = o%stiffness*spring_length(k)
               springs%exponent(k) = o%exponent
               springs%damping(k) = o%damping
               ! a side held by springs only: its first spring's obstacle gives the impulses
               ! there (the run statistics attribute contact episodes by side)
               if (o%side == 'below' .and. contacts%lower_obstacle(springs%point(k)) == 0) &
                  contacts%lower_obstacle(springs%point(k)) = spring_obstacle(k)
               if (o%side == 'above' .and. contacts%upper_obstacle(springs%point(k)) == 0) &
                  contacts%upper_obstacle(springs%point(k)) = spring_obstacle(k)
            end associate
         end do
      end associate
   end subroutine build_contact_points
end module vibrobeam_obstacles
