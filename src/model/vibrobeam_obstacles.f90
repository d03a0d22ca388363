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
!! - an obstacle with a `profile` takes its level at each node it covers from that table
!!   (x, level), linear between its points, instead of level_from/level_to; the table must
!!   span those nodes;
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
   use vibrobeam_status, only: stat_failure, stat_invalid_input
   use vibrobeam_kinds, only: dp
   use vibrobeam_text, only: real_text, integer_text
   use vibrobeam_schema_visitor, only: schema_visitor, real_row, integer_row, keyword_row, text_row, keyword_length, &
      path_length, unset, is_unset, unset_integer
   use vibrobeam_table_file, only: linear_table, read_table, outside_beam
   use vibrobeam_model, only: beam_model, node_row
   use vibrobeam_contact_set, only: contact_set, no_bound
   use vibrobeam_circle_set, only: circle_set
   use vibrobeam_planes, only: direction_shares
   implicit none
   private
   public :: obstacle_type, max_obstacles, visit_obstacles, build_contact_points, build_circle_points

   !> most obstacles a scene may hold (a tube through 100 baffles has 200 stops); memory and
   !! cost follow the obstacles given, this bounds only the reading of the input
   integer, parameter :: max_obstacles = 256

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
      !> file of (x, level) pairs (m, m), linear in between: the surface instead of
      !! level_from/level_to ('' = none)
      character(len=path_length) :: profile = ''
      !> 'level' (a flat side, bounds u from below or above: the default, '') | 'circle' (a
      !! round hole in the cross-section of a beam of two planes: R - |(v, w) - c| >= 0)
      character(len=keyword_length) :: shape = ''
      real(dp) :: radius = unset                    !! R of a circle (m)
      real(dp) :: center_y = unset, center_z = unset   !! its centre (m); unset: 0
      !> a polygon (shape = 'polygon': a broached hole, a bar support): its number of
      !! faces, `radius` the inscribed circle's, the first face's outward normal at
      !! `orientation` degrees from y towards z (unset: 0), the others every 360/sides
      integer :: sides = unset_integer
      real(dp) :: orientation = unset
      !> Coulomb's friction coefficient mu at a circle's wall (unset: 0, frictionless;
      !! listed only when given)
      real(dp) :: friction = unset
      !> Archard's wear coefficient K (m^3/(N m)) of the obstacle's wall, for the wear
      !! volume rate K W' (unset: none; a beam of two planes only, listed only when given)
      real(dp) :: wear_coefficient = unset
   contains
      procedure :: circle                           !! is it a circle?
      procedure :: hole                             !! a circle or a polygon (radius, centre)?
   end type obstacle_type

   !> What the obstacles make of the nodes 0..N (0 the clamp) while the contact points
   !! are built: the most restrictive bound of each side and its obstacle, the nodes a
   !! compliant obstacle covers, and the springs (node, obstacle, level, tributary length).
   type :: nodal_bounds
      real(dp), allocatable :: lower(:), upper(:)                    !! (0:N) bounds (m), +-no_bound: none
      integer, allocatable :: lower_source(:), upper_source(:)       !! (0:N) their obstacle, 0: none
      logical, allocatable :: covered(:)                             !! (0:N) a spring acts there
      integer :: springs = 0
      integer, allocatable :: spring_node(:), spring_obstacle(:)
      real(dp), allocatable :: spring_level(:), spring_length(:)     !! (m), (m; 1 for a punctual stop)
   contains
      procedure :: init => nodal_bounds_init
   end type nodal_bounds

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
         call visitor%variable(text_row('obstacles', 'profile', path_length, 'file of (x, level) pairs (m, m), '// &
                                        'linear in between: the surface, instead of level_from and level_to', n, i), &
                               o%profile)
         call visitor%variable(keyword_row('obstacles', 'shape', 'level|circle|polygon', keyword_length, &
                                           'level: a flat side (default); circle, polygon: a round or polygonal hole '// &
                                           'in the cross-section (&beam planes = 2)', n, i, optional=.true.), o%shape)
         call visitor%variable(integer_row('obstacles', 'sides', 3, 64, 'number of faces of a polygon', &
                                           optional=.true., extent=n, element=i), o%sides)
         call visitor%variable(real_row('obstacles', 'orientation', 'deg', -360.0_dp, 360.0_dp, &
                                        'direction of a polygon''s first face normal, from y towards z (default 0)', &
                                        n, i, optional=.true.), o%orientation)
         call visitor%variable(real_row('obstacles', 'radius', 'm', 1e-12_dp, 1e6_dp, &
                                        'radius of a circle', n, i, optional=.true.), o%radius)
         call visitor%variable(real_row('obstacles', 'center_y', 'm', -1e6_dp, 1e6_dp, &
                                        'centre of a circle in y (default 0)', n, i, optional=.true.), o%center_y)
         call visitor%variable(real_row('obstacles', 'center_z', 'm', -1e6_dp, 1e6_dp, &
                                        'centre of a circle in z (default 0)', n, i, optional=.true.), o%center_z)
         call visitor%variable(real_row('obstacles', 'friction', '', 0.0_dp, 10.0_dp, &
                                        'Coulomb friction coefficient mu at a circle''s wall (default 0)', n, i, &
                                        optional=.true.), o%friction)
         call visitor%variable(real_row('obstacles', 'wear_coefficient', 'm^3/(N m)', 0.0_dp, 1.0_dp, &
                                        'Archard''s wear coefficient K: wear volume rate K times the work rate', n, i, &
                                        optional=.true.), o%wear_coefficient)
      end subroutine visit_one
   end subroutine visit_obstacles

   !> Build the contact points of the obstacles on `model`'s mesh. Warnings (one line each) are
   !! appended to `warnings`; stat = stat_failure with a message when the obstacles contradict each
   !! other (a 'below' level at or above an 'above' level) or the clamp, stat_invalid_input
   !! when a profile cannot be read or does not fit (`read_profiles`).
   subroutine build_contact_points(obstacles, model, contacts, warnings, stat, errmsg)
      type(obstacle_type), intent(in) :: obstacles(:)
      type(beam_model), intent(in) :: model
      type(contact_set), intent(out) :: contacts
      character(len=:), allocatable, intent(inout) :: warnings
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      type(nodal_bounds) :: nodes
      type(linear_table) :: profiles(size(obstacles))
      integer :: k, first, last
      call read_profiles(obstacles, model, profiles, stat, errmsg)
      if (stat /= 0) return
      call nodes%init(model%elements, size(obstacles))
      do k = 1, size(obstacles)
         if (obstacles(k)%hole()) cycle   ! (`build_circle_points`)
         call covered_nodes(obstacles(k), k, model, first, last, warnings)
         call add_obstacle(obstacles(k), k, model, first, last, profiles(k), nodes)
      end do
      call check_bounds(nodes, model, stat, errmsg)
      if (stat /= 0) return
      call collect_points(nodes, model, contacts)
      call collect_springs(nodes, obstacles, contacts)
   end subroutine build_contact_points

   !> The contact points of the obstacles of a beam of two planes on `model`'s mesh
   !! (Hermite elements: the deflection at a node is one unknown): every node a circle
   !! covers (`covered_nodes`) whose deflection no support holds, and every node a level
   !! covers, a flat point (its side's inward normal (+-1, 0), its level at the node as for
   !! a planar beam, `level_at`). stat = stat_failure when two circles cover one node (one
   !! hole per node and plane of support, for now).
   subroutine build_circle_points(obstacles, model, circles, warnings, stat, errmsg)
      type(obstacle_type), intent(in) :: obstacles(:)
      type(beam_model), intent(in) :: model
      type(circle_set), intent(out) :: circles
      character(len=:), allocatable, intent(inout) :: warnings
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer :: source(0:model%elements), k, i, first, last, dofs(4), n
      integer, allocatable :: point_node(:), point_obstacle(:), point_face(:), point_first(:), point_last(:)
      real(dp) :: weights(4), side, outward(2), turn
      integer :: face
      stat = 0
      errmsg = ''
      source = 0
      allocate (point_node(0), point_obstacle(0), point_face(0), point_first(0), point_last(0))
      do k = 1, size(obstacles)
         call covered_nodes(obstacles(k), k, model, first, last, warnings)
         do i = first, last
            if (model%deflection_held(i)) cycle
            if (obstacles(k)%hole()) then
               if (source(i) /= 0) then
                  stat = stat_failure
                  errmsg = '&obstacles shape('//integer_text(k)//') = '''//trim(obstacles(k)%shape)//''' and shape('// &
                           integer_text(source(i))//') = '''//trim(obstacles(source(i))%shape)//''' both act at '// &
                           'the node x = '//real_text(model%x(i + 1))//' m: give one hole per node'
                  return
               end if
               source(i) = k
            end if
            ! a polygon: one flat point per face
            do face = 1, merge(obstacles(k)%sides, 1, obstacles(k)%shape == 'polygon')
               point_node = [point_node, i]
               point_obstacle = [point_obstacle, k]
               point_face = [point_face, face]
               point_first = [point_first, first]
               point_last = [point_last, last]
            end do
         end do
      end do
      ! the points by node, each node's in the obstacles' order
      n = size(point_node)
      circles%count = n
      allocate (circles%node(n), circles%x(n), circles%dof(n), circles%radius(n), circles%center(2, n), &
                circles%flat(n), circles%normal(2, n), circles%bound(n), circles%obstacle(n), circles%stiffness(n), &
                circles%exponent(n), circles%damping(n), circles%friction(n))
      k = 0
      do i = 0, model%elements
         do first = 1, n
            if (point_node(first) /= i) cycle
            k = k + 1
            circles%node(k) = i
            circles%x(k) = model%x(i + 1)
            call node_row(model, i, dofs, weights)
            circles%dof(k) = dofs(1)   ! Hermite: the node's deflection, weight 1 (`plane_rules`)
            circles%obstacle(k) = point_obstacle(first)
            associate (o => obstacles(point_obstacle(first)))
               circles%flat(k) = .not. o%circle()
               circles%radius(k) = 0
               circles%center(:, k) = 0
               circles%normal(:, k) = 0
               circles%bound(k) = 0
               if (o%hole()) then
                  circles%radius(k) = o%radius
                  circles%center(:, k) = [merge(0.0_dp, o%center_y, is_unset(o%center_y)), &
                                          merge(0.0_dp, o%center_z, is_unset(o%center_z))]
               end if
               if (o%shape == 'polygon') then
                  ! face f: o_f.(r - c) <= R, o_f its outward normal at orientation +
                  ! 360 (f - 1)/sides degrees; inward h = -o_f, bound -R - o_f.c
                  turn = merge(0.0_dp, o%orientation, is_unset(o%orientation)) + &
                         360.0_dp*(point_face(first) - 1)/o%sides
                  outward = direction_shares(turn)
                  circles%normal(:, k) = -outward
                  circles%bound(k) = -o%radius - dot_product(outward, circles%center(:, k))
               else if (.not. o%circle()) then   ! a level: y >= level below (h = (1, 0)), y <= level above (h = (-1, 0))
                  side = merge(1.0_dp, -1.0_dp, o%side == 'below')
                  circles%normal(:, k) = [side, 0.0_dp]
                  circles%bound(k) = side*level_at(o, model, i)
               end if
               ! a punctual obstacle: N/m^a at its node; a compliant circle, level or polygon
               ! along the beam gives each node its tributary share, as a planar level
               circles%stiffness(k) = o%stiffness
               if (o%stiffness > 0) &
                  circles%stiffness(k) = o%stiffness*spring_length(o, model, point_node(first), point_first(first) == &
                                                                   point_last(first))
               circles%exponent(k) = o%exponent
               circles%damping(k) = o%damping
               circles%friction(k) = merge(0.0_dp, o%friction, is_unset(o%friction))
            end associate
         end do
      end do
      circles%compliant = circles%count > 0 .and. all(circles%stiffness > 0)
   end subroutine build_circle_points

   !> The length (m) whose stiffness a compliant obstacle `o` gives node i (its spring
   !! k times it, N/m^a): 1 for a punctual one (the stiffness itself), x_to - x_from for
   !! one covering a single node (`alone`), else node i's tributary length inside [x_from,
   !! x_to] (h inside, h/2 at an end node).
   pure real(dp) function spring_length(o, model, i, alone)
      type(obstacle_type), intent(in) :: o
      type(beam_model), intent(in) :: model
      integer, intent(in) :: i
      logical, intent(in) :: alone
      if (alone) then
         spring_length = max(o%x_to - o%x_from, 0.0_dp)
         if (spring_length <= 1e-9_dp*model%h) spring_length = 1   ! punctual: the stiffness itself
      else
         spring_length = max(0.0_dp, min(o%x_to, model%x(i + 1) + 0.5_dp*model%h, model%length) - &
                             max(o%x_from, model%x(i + 1) - 0.5_dp*model%h))
      end if
   end function spring_length

   !> The level of obstacle `o` (without a profile) at node i: level_from, or linear from
   !! level_from at x_from to level_to at x_to (m).
   pure real(dp) function level_at(o, model, i)
      type(obstacle_type), intent(in) :: o
      type(beam_model), intent(in) :: model
      integer, intent(in) :: i
      real(dp) :: xi
      if (o%x_to - o%x_from <= 1e-9_dp*model%h .or. abs(o%level_to - o%level_from) <= 0) then
         level_at = o%level_from
      else
         xi = min(1.0_dp, max(0.0_dp, (model%x(i + 1) - o%x_from)/(o%x_to - o%x_from)))
         level_at = (1 - xi)*o%level_from + xi*o%level_to
      end if
   end function level_at

   !> Is obstacle `self` a circle (&obstacles shape = 'circle')?
   pure logical function circle(self)
      class(obstacle_type), intent(in) :: self
      circle = self%shape == 'circle'
   end function circle

   !> Is obstacle `self` a hole in the cross-section, a circle or a polygon (radius, centre)?
   pure logical function hole(self)
      class(obstacle_type), intent(in) :: self
      hole = self%shape == 'circle' .or. self%shape == 'polygon'
   end function hole

   !> The nodes first..last (0 the clamp) that obstacle k covers: the nearest node of a
   !! punctual one, every node in [x_from, x_to] of a longitudinal one (1e-9 h
   !! tolerance), the node nearest its middle when it covers none; a warning when a
   !! punctual one is not on a node or a longitudinal one covers no node.
   subroutine covered_nodes(o, k, model, first, last, warnings)
      type(obstacle_type), intent(in) :: o
      integer, intent(in) :: k
      type(beam_model), intent(in) :: model
      integer, intent(out) :: first, last
      character(len=:), allocatable, intent(inout) :: warnings
      character(len=160) :: line
      real(dp) :: tolerance
      tolerance = 1e-9_dp*model%h
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
   end subroutine covered_nodes

   !> Obstacle k at the nodes first..last: its level from its profile, or interpolated
   !! linearly along it (exactly level_from where level_to is the same); a
   !! rigid one tightens the bound of its side where it is more restrictive, a compliant
   !! one gives each node (but a held one) a spring of its tributary length inside
   !! [x_from, x_to] (h inside, h/2 at an end node; a punctual one its whole stiffness).
   subroutine add_obstacle(o, k, model, first, last, profile, nodes)
      type(obstacle_type), intent(in) :: o
      integer, intent(in) :: k, first, last
      type(beam_model), intent(in) :: model
      type(linear_table), intent(in) :: profile   !! the obstacle's profile (none: not allocated)
      type(nodal_bounds), intent(inout) :: nodes
      real(dp) :: level
      integer :: i, j
      do i = first, last
         if (allocated(profile%x)) then
            level = profile%at(model%x(i + 1))
         else
            level = level_at(o, model, i)
         end if
         if (o%stiffness > 0) then
            ! a spring, never a bound; a held node never moves and gets none
            if (model%deflection_held(i)) cycle
            nodes%covered(i) = .true.
            nodes%springs = nodes%springs + 1
            j = nodes%springs
            nodes%spring_node(j) = i
            nodes%spring_obstacle(j) = k
            nodes%spring_level(j) = level
            nodes%spring_length(j) = spring_length(o, model, i, first == last)
            cycle
         end if
         if (o%side == 'below') then
            if (level > nodes%lower(i)) then
               nodes%lower(i) = level
               nodes%lower_source(i) = k
            end if
         else
            if (level < nodes%upper(i)) then
               nodes%upper(i) = level
               nodes%upper_source(i) = k
            end if
         end if
      end do
   end subroutine add_obstacle

   !> The surface of each obstacle with a `profile` (docs/input.md, "&obstacles"): its
   !! table, every x in [0, L] and covering every node the obstacle acts at. stat =
   !! stat_invalid_input with a message naming the variable, the file (and line) and what
   !! is allowed. Obstacles without a profile get an empty table.
   subroutine read_profiles(obstacles, model, profiles, stat, errmsg)
      type(obstacle_type), intent(in) :: obstacles(:)
      type(beam_model), intent(in) :: model
      type(linear_table), intent(out) :: profiles(:)
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      character(len=:), allocatable :: shown, quiet
      integer :: k, first, last, n
      stat = 0
      errmsg = ''
      do k = 1, size(obstacles)
         if (len_trim(obstacles(k)%profile) == 0) cycle
         shown = '&obstacles profile('//integer_text(k)//') = '''//trim(obstacles(k)%profile)//''''
         call read_table(trim(obstacles(k)%profile), profiles(k), stat, errmsg)
         if (stat /= 0) then
            stat = stat_invalid_input
            errmsg = shown//': '//trim(errmsg)
            return
         end if
         n = size(profiles(k)%x)
         if (len(outside_beam(profiles(k), model%length)) > 0) then
            stat = stat_invalid_input
            errmsg = shown//outside_beam(profiles(k), model%length)
            return
         end if
         ! a node within round-off (1e-9 h, as covered_nodes) of an end takes the end's level
         profiles(k)%hold_ends = .true.
         quiet = ''   ! the nodes only: covered_nodes warns once, in build_contact_points
         call covered_nodes(obstacles(k), k, model, first, last, quiet)
         if (model%x(first + 1) < profiles(k)%x(1) - 1e-9_dp*model%h .or. &
             model%x(last + 1) > profiles(k)%x(n) + 1e-9_dp*model%h) then
            stat = stat_invalid_input
            errmsg = shown//' spans x in ['//real_text(profiles(k)%x(1))//', '//real_text(profiles(k)%x(n))// &
                     '] m, but obstacle '//integer_text(k)//' acts at the nodes from x = '// &
                     real_text(model%x(first + 1))//' to '//real_text(model%x(last + 1))//' m: the profile must '// &
                     'span every node in [x_from, x_to]'
            return
         end if
      end do
   end subroutine read_profiles

   !> stat = stat_failure when a bound cuts a support (u = 0 must be admissible at a node
   !! whose deflection a support holds) or a 'below' level is not under an 'above' level at
   !! a node.
   subroutine check_bounds(nodes, model, stat, errmsg)
      type(nodal_bounds), intent(in) :: nodes
      type(beam_model), intent(in) :: model
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer :: i
      stat = 0
      errmsg = ''
      do i = 0, model%elements
         if (.not. model%deflection_held(i)) cycle
         if (nodes%lower(i) > 0 .or. nodes%upper(i) < 0) then
            if (i == 0 .and. model%boundary%holds_rotation(1)) then
               write (errmsg, '(a,i0,a)') '&obstacles: obstacle ', max(nodes%lower_source(0), nodes%upper_source(0)), &
                  ' cuts the clamped end x = 0, where u = 0 always; move x_from away from 0 or its level past 0'
            else
               errmsg = '&obstacles: obstacle '//integer_text(max(nodes%lower_source(i), nodes%upper_source(i)))// &
                        ' (level '//real_text(merge(nodes%lower(i), nodes%upper(i), nodes%lower(i) > 0))// &
                        ' m there) cuts the support at x = '//real_text(model%x(i + 1))// &
                        ' m, where u = 0 always; move it away from the support or its level past 0'
            end if
            stat = stat_failure
            return
         end if
      end do
      do i = 0, model%elements
         if (model%deflection_held(i)) cycle
         if (nodes%lower(i) >= nodes%upper(i)) then
            write (errmsg, '(a,i0,a,g0.6,a,i0,a,g0.6,a,g0.6,a)') '&obstacles: the ''below'' obstacle ', &
               nodes%lower_source(i), ' (level ', nodes%lower(i), ' m) is not under the ''above'' obstacle ', &
               nodes%upper_source(i), ' (level ', nodes%upper(i), ' m) at x = ', model%x(i + 1), &
               ' m; a below level must be smaller than an above level'
            stat = stat_failure
            return
         end if
      end do
   end subroutine check_bounds

   !> A contact point at every node whose deflection no support holds with a bound or a
   !! spring, in the order of the nodes.
   subroutine collect_points(nodes, model, contacts)
      type(nodal_bounds), intent(in) :: nodes
      type(beam_model), intent(in) :: model
      type(contact_set), intent(inout) :: contacts
      integer :: i, c
      associate (lower => nodes%lower, upper => nodes%upper)
         contacts%count = count((lower > -no_bound .or. upper < no_bound .or. nodes%covered) .and. &
                                .not. model%deflection_held)
         allocate (contacts%node(contacts%count), contacts%x(contacts%count), contacts%lower(contacts%count), &
                   contacts%upper(contacts%count), contacts%dofs(4, contacts%count), &
                   contacts%weights(4, contacts%count), contacts%lower_obstacle(contacts%count), &
                   contacts%upper_obstacle(contacts%count))
         c = 0
         do i = 0, model%elements
            if (model%deflection_held(i)) cycle
            if (lower(i) <= -no_bound .and. upper(i) >= no_bound .and. .not. nodes%covered(i)) cycle
            c = c + 1
            contacts%node(c) = i
            contacts%x(c) = model%x(i + 1)
            contacts%lower(c) = lower(i)
            contacts%upper(c) = upper(i)
            contacts%lower_obstacle(c) = nodes%lower_source(i)
            contacts%upper_obstacle(c) = nodes%upper_source(i)
            call node_row(model, i, contacts%dofs(:, c), contacts%weights(:, c))
         end do
      end associate
   end subroutine collect_points

   !> The springs of the compliant obstacles at their contact points; a side held by
   !! springs only takes its first spring's obstacle (the run statistics attribute
   !! contact episodes by side).
   subroutine collect_springs(nodes, obstacles, contacts)
      type(nodal_bounds), intent(in) :: nodes
      type(obstacle_type), intent(in) :: obstacles(:)
      type(contact_set), intent(inout) :: contacts
      integer :: j, k
      j = nodes%springs
      associate (springs => contacts%springs)
         springs%count = j
         allocate (springs%point(j), springs%sign(j), springs%level(j), springs%stiffness(j), &
                   springs%exponent(j), springs%damping(j))
         do k = 1, j
            springs%point(k) = findloc(contacts%node, nodes%spring_node(k), 1)
            associate (o => obstacles(nodes%spring_obstacle(k)))
               springs%sign(k) = merge(1.0_dp, -1.0_dp, o%side == 'below')
               springs%level(k) = nodes%spring_level(k)
               springs%stiffness(k) = o%stiffness*nodes%spring_length(k)
               springs%exponent(k) = o%exponent
               springs%damping(k) = o%damping
               if (o%side == 'below' .and. contacts%lower_obstacle(springs%point(k)) == 0) &
                  contacts%lower_obstacle(springs%point(k)) = nodes%spring_obstacle(k)
               if (o%side == 'above' .and. contacts%upper_obstacle(springs%point(k)) == 0) &
                  contacts%upper_obstacle(springs%point(k)) = nodes%spring_obstacle(k)
            end associate
         end do
      end associate
   end subroutine collect_springs

   !> Empty bounds at nodes 0..elements, room for a spring of each obstacle at each node.
   subroutine nodal_bounds_init(self, elements, obstacles)
      class(nodal_bounds), intent(out) :: self
      integer, intent(in) :: elements, obstacles
      allocate (self%lower(0:elements), source=-no_bound)
      allocate (self%upper(0:elements), source=no_bound)
      allocate (self%lower_source(0:elements), self%upper_source(0:elements), source=0)
      allocate (self%covered(0:elements), source=.false.)
      allocate (self%spring_node(obstacles*(elements + 1)), self%spring_obstacle(obstacles*(elements + 1)))
      allocate (self%spring_level(obstacles*(elements + 1)), self%spring_length(obstacles*(elements + 1)))
      self%springs = 0
   end subroutine nodal_bounds_init
end module vibrobeam_obstacles
