!> Reading a scene from a namelist file (INTERFACE.md, "Input: namelist groups").
!!
!! Every group is optional. A group is read with Fortran namelist input, so an unknown
!! variable or a malformed value is reported by the run-time library; we add the group's
!! name. Before reading, the file is scanned for group names so that a misspelt group
!! (which namelist input would silently skip) is an error too.
module vibrobeam_input
   use vibrobeam_kinds, only: dp
   use vibrobeam_scene, only: scene_type, max_obstacles, max_points, unset, is_unset
   implicit none
   private
   public :: read_scene

   character(len=*), parameter :: known_groups(10) = [character(len=9) :: 'beam', 'mesh', &
      'analysis', 'obstacles', 'impact', 'time', 'initial', 'load', 'solver', 'output']

contains

   !> Read `filename` into `scene` (defaults for everything not given). stat = 0 on
   !! success, 1 with a message naming the group and variable otherwise. Validation of the
   !! values is `validate_scene`'s job; this routine only checks what it must to read.
   subroutine read_scene(filename, scene, stat, errmsg)
      character(len=*), intent(in) :: filename
      type(scene_type), intent(out) :: scene
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer :: unit
      character(len=256) :: iomsg
      stat = 0
      errmsg = ''
      allocate (scene%obstacles(0), scene%points(0))
      open (newunit=unit, file=filename, status='old', action='read', iostat=stat, iomsg=iomsg)
      if (stat /= 0) then
         stat = 1
         errmsg = 'cannot open input file '''//trim(filename)//''': '//trim(iomsg)
         return
      end if
      call check_group_names(unit, stat, errmsg)
      if (stat == 0) call read_beam(unit, scene, stat, errmsg)
      if (stat == 0) call read_mesh(unit, scene, stat, errmsg)
      if (stat == 0) call read_analysis(unit, scene, stat, errmsg)
      if (stat == 0) call read_obstacles(unit, scene, stat, errmsg)
      if (stat == 0) call read_impact(unit, scene, stat, errmsg)
      if (stat == 0) call read_time(unit, scene, stat, errmsg)
      if (stat == 0) call read_initial(unit, scene, stat, errmsg)
      if (stat == 0) call read_load(unit, scene, stat, errmsg)
      if (stat == 0) call read_solver(unit, scene, stat, errmsg)
      if (stat == 0) call read_output(unit, scene, stat, errmsg)
      close (unit)
   end subroutine read_scene

   !> Every line whose first non-blank character is '&' must open a known group, once.
   subroutine check_group_names(unit, stat, errmsg)
      integer, intent(in) :: unit
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      character(len=1024) :: line
      character(len=64) :: name
      logical :: seen(size(known_groups))
      integer :: ios, line_number, k, last
      seen = .false.
      line_number = 0
      stat = 0
      errmsg = ''
      rewind (unit)
      do
         read (unit, '(a)', iostat=ios) line
         if (ios /= 0) exit
         line_number = line_number + 1
         line = adjustl(line)
         if (line(1:1) /= '&') cycle
         last = scan(line(2:), ' ,/!'//achar(9))
         if (last == 0) last = len_trim(line)
         name = lowercase(line(2:last))
         if (len_trim(name) == 0 .or. trim(name) == 'end') cycle   ! '&end' closes a group in old style
         k = findloc(known_groups, trim(name), dim=1)
         if (k == 0) then
            write (errmsg, '(a,i0,a)') 'line ', line_number, ': unknown namelist group &'//trim(name)// &
               ' (known: &beam &mesh &analysis &obstacles &impact &time &initial &load &solver &output)'
            stat = 1
            return
         end if
         if (seen(k)) then
            write (errmsg, '(a,i0,a)') 'line ', line_number, ': group &'//trim(name)//' appears twice'
            stat = 1
            return
         end if
         seen(k) = .true.
      end do
   end subroutine check_group_names

   !> Turn a namelist read status into stat/errmsg: end of file means the group is absent.
   !! The run-time library reports an unknown variable and a malformed value alike, as
   !! "Cannot match namelist object name X"; we look X up in the group's text to say which:
   !! X followed by '=' (or '(') is an unknown variable, otherwise X is part of the value of
   !! the variable assigned just before it.
   subroutine read_status(unit, group, ios, iomsg, stat, errmsg)
      integer, intent(in) :: unit
      character(len=*), intent(in) :: group, iomsg
      integer, intent(in) :: ios
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      character(len=*), parameter :: marker = 'object name '
      character(len=:), allocatable :: text, token
      character(len=1) :: next
      integer :: where_token, after, before, name_end, name_start
      stat = 0
      errmsg = ''
      if (is_iostat_end(ios) .or. ios == 0) return
      stat = 1
      errmsg = '&'//group//': '//trim(iomsg)//' (unknown variable or malformed value)'
      where_token = index(iomsg, marker)
      if (where_token == 0) return
      token = trim(lowercase(iomsg(where_token + len(marker):)))
      if (len(token) == 0) return
      text = lowercase(group_text(unit, group))
      where_token = token_position(text, token)
      if (where_token == 0) return
      after = where_token + len(token) - 1 + verify(text(where_token + len(token):)//'x', ' ')
      next = text(after:after)
      if (next == '=' .or. next == '(') then
         errmsg = '&'//group//': unknown variable '''//token//''''
         return
      end if
      before = index(text(1:where_token - 1), '=', back=.true.)
      if (before <= 1) return
      name_end = len_trim(text(1:before - 1))
      if (name_end == 0) return
      if (text(name_end:name_end) == ')') name_end = index(text(1:name_end), '(', back=.true.) - 1
      if (name_end <= 0) return
      name_start = scan(text(1:name_end), ' ,&'//achar(9), back=.true.) + 1
      errmsg = '&'//group//' '//text(name_start:name_end)//': malformed value near '''//token// &
               ''' (a number, a quoted string or .true./.false. is expected)'
   contains
      !> Position of `word` in `line` as a whole token (not the end of a longer name), 0 if
      !! absent.
      pure integer function token_position(line, word)
         character(len=*), intent(in) :: line, word
         character(len=*), parameter :: name_characters = 'abcdefghijklmnopqrstuvwxyz0123456789_'
         integer :: start, found
         token_position = 0
         start = 1
         do
            found = index(line(start:), word)
            if (found == 0) return
            found = start + found - 1
            if (found == 1) then
               token_position = found
               return
            end if
            if (index(name_characters, line(found - 1:found - 1)) == 0 .or. word(1:1) == '.') then
               token_position = found
               return
            end if
            start = found + 1
         end do
      end function token_position
   end subroutine read_status

   !> The text of group &name in the file (its lines joined by blanks, up to and including
   !! the '/' that closes it outside quotes, comments left out); '' if the group is absent.
   function group_text(unit, name) result(text)
      integer, intent(in) :: unit
      character(len=*), intent(in) :: name
      character(len=:), allocatable :: text
      character(len=1024) :: line
      character(len=1) :: quote
      integer :: ios, i, first, last
      logical :: inside
      text = ''
      inside = .false.
      quote = ' '
      rewind (unit)
      do
         read (unit, '(a)', iostat=ios) line
         if (ios /= 0) return
         if (.not. inside) then
            first = index(lowercase(line), '&'//name)
            if (first == 0) cycle
            last = first + len(name) + 1
            if (last <= len(line)) then
               if (scan(line(last:last), ' ,/!'//achar(9)) == 0) cycle   ! a longer group name
            end if
            inside = .true.
            line = line(last:)
         end if
         do i = 1, len_trim(line)
            if (quote /= ' ') then
               if (line(i:i) == quote) quote = ' '
            else if (line(i:i) == achar(39) .or. line(i:i) == achar(34)) then
               quote = line(i:i)
            else if (line(i:i) == '!') then
               exit
            else if (line(i:i) == '/') then
               text = text//' '//line(1:i)
               return
            end if
         end do
         text = text//' '//line(1:i - 1)
      end do
   end function group_text

   subroutine read_beam(unit, scene, stat, errmsg)
      integer, intent(in) :: unit
      type(scene_type), intent(inout) :: scene
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      real(dp) :: length, k2, youngs_modulus, density, area, inertia, rayleigh_mass, rayleigh_stiffness
      namelist /beam/ length, k2, youngs_modulus, density, area, inertia, rayleigh_mass, rayleigh_stiffness
      integer :: ios
      character(len=256) :: iomsg
      length = scene%length; k2 = scene%k2
      youngs_modulus = scene%youngs_modulus; density = scene%density
      area = scene%area; inertia = scene%inertia
      rayleigh_mass = scene%rayleigh_mass; rayleigh_stiffness = scene%rayleigh_stiffness
      rewind (unit)
      read (unit, nml=beam, iostat=ios, iomsg=iomsg)
      call read_status(unit, 'beam', ios, iomsg, stat, errmsg)
      scene%length = length; scene%k2 = k2
      scene%youngs_modulus = youngs_modulus; scene%density = density
      scene%area = area; scene%inertia = inertia
      scene%rayleigh_mass = rayleigh_mass; scene%rayleigh_stiffness = rayleigh_stiffness
   end subroutine read_beam

   subroutine read_mesh(unit, scene, stat, errmsg)
      integer, intent(in) :: unit
      type(scene_type), intent(inout) :: scene
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer :: elements
      character(len=64) :: basis
      namelist /mesh/ elements, basis
      integer :: ios
      character(len=256) :: iomsg
      elements = scene%elements
      basis = scene%basis
      rewind (unit)
      read (unit, nml=mesh, iostat=ios, iomsg=iomsg)
      call read_status(unit, 'mesh', ios, iomsg, stat, errmsg)
      scene%elements = elements
      scene%basis = lowercase(basis)
   end subroutine read_mesh

   subroutine read_analysis(unit, scene, stat, errmsg)
      integer, intent(in) :: unit
      type(scene_type), intent(inout) :: scene
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      character(len=64) :: kind
      integer :: modes
      namelist /analysis/ kind, modes
      integer :: ios
      character(len=256) :: iomsg
      kind = scene%kind
      modes = scene%modes
      rewind (unit)
      read (unit, nml=analysis, iostat=ios, iomsg=iomsg)
      call read_status(unit, 'analysis', ios, iomsg, stat, errmsg)
      scene%kind = lowercase(kind)
      scene%modes = modes
   end subroutine read_analysis

   subroutine read_obstacles(unit, scene, stat, errmsg)
      integer, intent(in) :: unit
      type(scene_type), intent(inout) :: scene
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer :: count
      character(len=64) :: side(max_obstacles)
      real(dp), dimension(max_obstacles) :: x_from, x_to, level_from, level_to
      namelist /obstacles/ count, side, x_from, x_to, level_from, level_to
      integer :: ios, i
      character(len=256) :: iomsg
      character(len=16) :: number
      count = 0
      side = ''
      x_from = unset; x_to = unset; level_from = unset; level_to = unset
      rewind (unit)
      read (unit, nml=obstacles, iostat=ios, iomsg=iomsg)
      call read_status(unit, 'obstacles', ios, iomsg, stat, errmsg)
      if (stat /= 0) return
      write (number, '(i0)') count
      if (count < 0 .or. count > max_obstacles) then
         stat = 1
         write (errmsg, '(a,i0,a)') '&obstacles count = '//trim(number)//' is outside [0, ', max_obstacles, ']'
         return
      end if
      do i = count + 1, max_obstacles
         if (side(i) /= '' .or. .not. is_unset(x_from(i)) .or. .not. is_unset(x_to(i)) .or. &
             .not. is_unset(level_from(i)) .or. .not. is_unset(level_to(i))) then
            stat = 1
            write (errmsg, '(a,i0,a)') '&obstacles: obstacle ', i, ' is described but count = '// &
               trim(number)//'; raise count or remove it'
            return
         end if
      end do
      deallocate (scene%obstacles)
      allocate (scene%obstacles(count))
      do i = 1, count
         write (number, '(i0)') i
         if (side(i) == '') then
            stat = 1
            errmsg = '&obstacles side('//trim(number)//') is missing: give ''below'' or ''above'''
            return
         end if
         if (is_unset(level_from(i))) then
            stat = 1
            errmsg = '&obstacles level_from('//trim(number)//') is missing: give the height (m) of the obstacle surface'
            return
         end if
         scene%obstacles(i)%side = lowercase(side(i))
         scene%obstacles(i)%x_from = merge(scene%length, x_from(i), is_unset(x_from(i)))
         scene%obstacles(i)%x_to = merge(scene%obstacles(i)%x_from, x_to(i), is_unset(x_to(i)))
         scene%obstacles(i)%level_from = level_from(i)
         scene%obstacles(i)%level_to = merge(level_from(i), level_to(i), is_unset(level_to(i)))
      end do
   end subroutine read_obstacles

   subroutine read_impact(unit, scene, stat, errmsg)
      integer, intent(in) :: unit
      type(scene_type), intent(inout) :: scene
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      real(dp) :: restitution
      character(len=64) :: separating_points
      namelist /impact/ restitution, separating_points
      integer :: ios
      character(len=256) :: iomsg
      restitution = scene%restitution
      separating_points = scene%separating_points
      rewind (unit)
      read (unit, nml=impact, iostat=ios, iomsg=iomsg)
      call read_status(unit, 'impact', ios, iomsg, stat, errmsg)
      scene%restitution = restitution
      scene%separating_points = lowercase(separating_points)
   end subroutine read_impact

   subroutine read_time(unit, scene, stat, errmsg)
      integer, intent(in) :: unit
      type(scene_type), intent(inout) :: scene
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      real(dp) :: t_end, dt, theta, gamma
      character(len=64) :: scheme
      namelist /time/ t_end, dt, scheme, theta, gamma
      integer :: ios
      character(len=256) :: iomsg
      t_end = scene%t_end; dt = scene%dt; scheme = scene%scheme
      theta = scene%theta; gamma = scene%gamma
      rewind (unit)
      read (unit, nml=time, iostat=ios, iomsg=iomsg)
      call read_status(unit, 'time', ios, iomsg, stat, errmsg)
      scene%t_end = t_end; scene%dt = dt; scene%scheme = lowercase(scheme)
      scene%theta = theta; scene%gamma = gamma
   end subroutine read_time

   subroutine read_initial(unit, scene, stat, errmsg)
      integer, intent(in) :: unit
      type(scene_type), intent(inout) :: scene
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      character(len=64) :: displacement, velocity
      integer :: displacement_mode, velocity_mode
      real(dp) :: displacement_amplitude, velocity_amplitude
      character(len=len(scene%from_file)) :: from_file
      namelist /initial/ displacement, displacement_mode, displacement_amplitude, &
         velocity, velocity_mode, velocity_amplitude, from_file
      integer :: ios
      character(len=256) :: iomsg
      displacement = scene%displacement; displacement_mode = scene%displacement_mode
      displacement_amplitude = scene%displacement_amplitude
      velocity = scene%velocity; velocity_mode = scene%velocity_mode
      velocity_amplitude = scene%velocity_amplitude
      from_file = scene%from_file
      rewind (unit)
      read (unit, nml=initial, iostat=ios, iomsg=iomsg)
      call read_status(unit, 'initial', ios, iomsg, stat, errmsg)
      scene%displacement = lowercase(displacement); scene%displacement_mode = displacement_mode
      scene%displacement_amplitude = displacement_amplitude
      scene%velocity = lowercase(velocity); scene%velocity_mode = velocity_mode
      scene%velocity_amplitude = velocity_amplitude
      scene%from_file = from_file
   end subroutine read_initial

   subroutine read_load(unit, scene, stat, errmsg)
      integer, intent(in) :: unit
      type(scene_type), intent(inout) :: scene
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      real(dp) :: distributed, distributed_frequency, distributed_phase
      real(dp) :: point_force, point_position, point_frequency, base_amplitude, base_frequency
      namelist /load/ distributed, distributed_frequency, distributed_phase, point_force, &
         point_position, point_frequency, base_amplitude, base_frequency
      integer :: ios
      character(len=256) :: iomsg
      distributed = scene%distributed; distributed_frequency = scene%distributed_frequency
      distributed_phase = scene%distributed_phase; point_force = scene%point_force
      point_position = scene%length; point_frequency = scene%point_frequency
      base_amplitude = scene%base_amplitude; base_frequency = scene%base_frequency
      rewind (unit)
      read (unit, nml=load, iostat=ios, iomsg=iomsg)
      call read_status(unit, 'load', ios, iomsg, stat, errmsg)
      scene%distributed = distributed; scene%distributed_frequency = distributed_frequency
      scene%distributed_phase = distributed_phase; scene%point_force = point_force
      scene%point_position = point_position; scene%point_frequency = point_frequency
      scene%base_amplitude = base_amplitude; scene%base_frequency = base_frequency
   end subroutine read_load

   subroutine read_solver(unit, scene, stat, errmsg)
      integer, intent(in) :: unit
      type(scene_type), intent(inout) :: scene
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      character(len=64) :: contact_solver, contact_method
      integer :: contact_max_iterations
      namelist /solver/ contact_solver, contact_method, contact_max_iterations
      integer :: ios
      character(len=256) :: iomsg
      contact_solver = scene%contact_solver
      contact_method = scene%contact_method
      contact_max_iterations = scene%contact_max_iterations
      rewind (unit)
      read (unit, nml=solver, iostat=ios, iomsg=iomsg)
      call read_status(unit, 'solver', ios, iomsg, stat, errmsg)
      scene%contact_solver = lowercase(contact_solver)
      scene%contact_method = lowercase(contact_method)
      scene%contact_max_iterations = contact_max_iterations
   end subroutine read_solver

   subroutine read_output(unit, scene, stat, errmsg)
      integer, intent(in) :: unit
      type(scene_type), intent(inout) :: scene
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      character(len=len(scene%file)) :: file
      integer :: every, field_every
      logical :: text, progress
      real(dp) :: points(max_points), measure_from, checkpoint_seconds, episode_gap
      namelist /output/ file, every, text, progress, field_every, points, measure_from, checkpoint_seconds, &
         episode_gap
      integer :: ios, count_points
      character(len=256) :: iomsg
      file = scene%file; every = scene%every; text = scene%text; progress = scene%progress
      field_every = scene%field_every; measure_from = scene%measure_from
      checkpoint_seconds = scene%checkpoint_seconds; episode_gap = scene%episode_gap
      points = unset
      rewind (unit)
      read (unit, nml=output, iostat=ios, iomsg=iomsg)
      call read_status(unit, 'output', ios, iomsg, stat, errmsg)
      scene%file = file; scene%every = every; scene%text = text; scene%progress = progress
      scene%field_every = field_every; scene%measure_from = measure_from
      scene%checkpoint_seconds = checkpoint_seconds; scene%episode_gap = episode_gap
      ! the points given are the leading ones of the list
      count_points = 0
      do while (count_points < max_points)
         if (is_unset(points(count_points + 1))) exit
         count_points = count_points + 1
      end do
      scene%points = points(1:count_points)
   end subroutine read_output

   !> ASCII lower case.
   pure function lowercase(text) result(lower)
      character(len=*), intent(in) :: text
      character(len=len(text)) :: lower
      integer :: i, code
      lower = text
      do i = 1, len(text)
         code = iachar(text(i:i))
         if (code >= iachar('A') .and. code <= iachar('Z')) lower(i:i) = achar(code + 32)
      end do
   end function lowercase
end module vibrobeam_input
