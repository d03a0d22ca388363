!> Whether a scene may continue the checkpoint of an earlier result (docs/output.md,
!! "Checkpoint and restart"; `&initial from_file`, and a sweep that starts from a file):
!! the scene must match the file in its model (basis, elements, reduction, length, beam
!! data, bending planes and inertia_z, supports, springs, point masses, sections and axial
!! force), its time scheme (scheme, dt, theta, gamma) and its contact points (count and x;
!! a beam of two planes: the points of its obstacles, count and x); a single run's
!! continuation also in its compliant stops (a compliant hole: its shape and size too). Loads, restitution, rigid
!! obstacle levels, a stop's damping and outputs may change. Reading the checkpoint itself
!! is `vibrobeam_checkpoint`'s.
module vibrobeam_restart_check
   use vibrobeam_status, only: stat_failure
   use vibrobeam_kinds, only: dp, int64
   use vibrobeam_text, only: integer_text, real_text
   use vibrobeam_scene, only: scene_type, scene_entry, scene_entries
   use vibrobeam_hdf5_reader, only: h5_reader
   use vibrobeam_checkpoint, only: no_checkpoint, same_bits
   implicit none
   private
   public :: check_compatible

   !> Root attributes (resolved input) that must match between a checkpoint and the scene
   !! that continues it: what the state's unknowns are (the model) and what its velocities
   !! mean (the time scheme).
   character(len=*), parameter :: matching(12) = [character(len=32) :: 'mesh.basis', 'mesh.elements', &
      'mesh.reduction', 'beam.length', 'beam.mass_per_length', 'beam.bending_stiffness', 'beam.rayleigh_mass', &
      'beam.rayleigh_stiffness', 'time.scheme', 'time.dt', 'time.theta', 'time.gamma']
   !> Why the model, the time scheme and the contact points must match (end of a message).
   character(len=*), parameter :: model_why = '; the model (basis, elements, reduction, length, beam data), the '// &
      'time scheme (scheme, dt, theta, gamma) and the contact points (a beam of two planes: the points of '// &
      'its obstacles) must match'
   !> Why a compliant stop must match (end of a message).
   character(len=*), parameter :: stops_why = '; a compliant stop''s force and stored energy are part of '// &
      'the checkpoint: each obstacle keeps its kind (rigid or compliant), and a compliant one its side, '// &
      'extent, levels, stiffness and exponent (its damping may change, rigid obstacles may move)'

contains

   !> Check that `filename`'s run matches `scene` in its model and time scheme
   !! (`matching`) and has the contact points `contact_x`; with `stops` (a run that
   !! continues the checkpoint, not a sweep that starts from its U and V), also in its
   !! compliant stops: a stop's force and stored energy are part of the state that a run
   !! continues (the running sums of the energy balance include them), so every obstacle
   !! that is compliant in the file or in the scene keeps its kind, side, extent, levels,
   !! stiffness and exponent; its damping may change, and so may rigid obstacles (their
   !! levels are checked against the state by the caller). stat = stat_failure with a message naming
   !! the first mismatch. `same_bounds`: the obstacle bounds at the contact points are
   !! those of the file.
   subroutine check_compatible(filename, scene, contact_x, lower, upper, same_bounds, stat, errmsg, stops, hole_x)
      character(len=*), intent(in) :: filename
      type(scene_type), intent(in) :: scene
      real(dp), intent(in) :: contact_x(:), lower(:), upper(:)
      logical, intent(out) :: same_bounds
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      logical, intent(in), optional :: stops
      real(dp), intent(in), optional :: hole_x(:)   !! a beam of two planes: its obstacles' points
      type(h5_reader) :: file
      type(scene_entry), allocatable :: list(:)
      character(len=:), allocatable :: prefix
      real(dp), allocatable :: file_lower(:), file_upper(:)
      same_bounds = .false.
      prefix = '&initial from_file = '''//trim(filename)//''': '
      call file%open(filename, stat, errmsg)
      if (stat /= 0) then
         errmsg = prefix//trim(errmsg)
         return
      end if
      allocate (list, source=scene_entries(scene))
      compare: block
         if (.not. file%exists('/checkpoint')) then
            call no_checkpoint(filename, stat, errmsg)
            errmsg = prefix//trim(errmsg)
            exit compare
         end if
         call compare_model(file, list, prefix, stat, errmsg)
         if (stat /= 0) exit compare
         call compare_structure(file, list, prefix, stat, errmsg)
         if (stat /= 0) exit compare
         call compare_planes(file, list, prefix, stat, errmsg)
         if (stat /= 0) exit compare
         call compare_points(file, '/contact/x', 'contact point', contact_x, prefix, stat, errmsg)
         if (stat /= 0) exit compare
         if (present(hole_x)) then
            if (size(hole_x) > 0 .or. file%exists('/wear/x')) &
               call compare_points(file, '/wear/x', 'point of the obstacles', hole_x, prefix, stat, errmsg)
            if (stat /= 0) exit compare
         end if
         if (present(stops)) then
            if (stops) call compare_stops(file, scene, list, prefix, stat, errmsg)
            if (stat /= 0) exit compare
         end if
         call file%read_reals('/contact/lower', file_lower, stat, errmsg)
         if (stat == 0) call file%read_reals('/contact/upper', file_upper, stat, errmsg)
         if (stat /= 0) then
            errmsg = prefix//trim(errmsg)
            exit compare
         end if
         same_bounds = all(same_bits(file_lower, lower)) .and. all(same_bits(file_upper, upper))
         if (present(hole_x)) same_bounds = same_bounds .and. same_walls(file, list)
      end block compare
      call file%close()
   end subroutine check_compatible

   !> The index of the last entry of `list` named `name` (the one that holds, as in a
   !! namelist), 0 when none is.
   pure integer function entry_index(list, name) result(e)
      type(scene_entry), intent(in) :: list(:)
      character(len=*), intent(in) :: name
      do e = size(list), 1, -1
         if (list(e)%name == name) return
      end do
      e = 0
   end function entry_index

   !> The root attributes of `matching` in the file against the scene's entries `list`.
   subroutine compare_model(file, list, prefix, stat, errmsg)
      type(h5_reader), intent(in) :: file
      type(scene_entry), intent(in) :: list(:)
      character(len=*), intent(in) :: prefix
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      character(len=:), allocatable :: why
      integer :: i, k
      stat = 0
      errmsg = ''
      do k = 1, size(matching)
         i = entry_index(list, matching(k))
         if (i == 0) cycle
         why = model_why
         if (matching(k) == 'mesh.reduction') why = ': a reduced run''s state holds reduced coordinates, '// &
            'not the values of the mesh'
         call compare_entry(file, list(i), prefix, why, stat, errmsg)
         if (stat /= 0) return
      end do
   end subroutine compare_model

   !> The supports, springs, point masses, sections and axial force (&beam left_end,
   !! right_end, its springs and axial_force, &supports, &masses, &sections): listed only
   !! when given, so each is compared as resolved (the ends clamped-free, the springs and
   !! the force 0, the groups empty when absent), then element by element.
   subroutine compare_structure(file, list, prefix, stat, errmsg)
      type(h5_reader), intent(in) :: file
      type(scene_entry), intent(in) :: list(:)
      character(len=*), intent(in) :: prefix
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      character(len=*), parameter :: ends(2) = [character(len=9) :: 'left_end', 'right_end']
      character(len=*), parameter :: defaults(2) = [character(len=7) :: 'clamped', 'free']
      character(len=*), parameter :: springs(5) = [character(len=23) :: 'left_spring', 'left_rotational_spring', &
                                                   'right_spring', 'right_rotational_spring', 'axial_force']
      character(len=*), parameter :: groups(3) = [character(len=8) :: 'supports', 'masses', 'sections']
      character(len=*), parameter :: why = '; the supports, springs, point masses, sections and axial force make '// &
                                           'the model''s unknowns, stiffness and mass: they must match'
      character(len=:), allocatable :: in_file, in_scene, name
      real(dp) :: file_value, scene_value
      integer(int64) :: file_count, scene_count
      integer :: k, e
      stat = 0
      errmsg = ''
      do k = 1, 2
         name = 'beam.'//trim(ends(k))
         in_file = trim(defaults(k))
         if (file%has_attr('/', name)) call file%attr_string('/', name, in_file, stat, errmsg)
         if (stat /= 0) return
         in_scene = trim(defaults(k))
         e = entry_index(list, name)
         if (e > 0) in_scene = trim(list(e)%string_value)
         if (in_file /= in_scene) then
            call mismatch(prefix, name, ''''//in_file//'''', ''''//in_scene//'''', why, stat, errmsg)
            return
         end if
      end do
      do k = 1, size(springs)
         name = 'beam.'//trim(springs(k))
         file_value = 0
         if (file%has_attr('/', name)) call file%attr_real('/', name, file_value, stat, errmsg)
         if (stat /= 0) return
         scene_value = 0
         e = entry_index(list, name)
         if (e > 0) scene_value = list(e)%real_value
         if (.not. same_bits(file_value, scene_value)) then
            call mismatch(prefix, name, real_text(file_value), real_text(scene_value), why, stat, errmsg)
            return
         end if
      end do
      do k = 1, size(groups)
         name = trim(groups(k))//'.count'
         file_count = 0
         if (file%has_attr('/', name)) call file%attr_int64('/', name, file_count, stat, errmsg)
         if (stat /= 0) return
         scene_count = 0
         e = entry_index(list, name)
         if (e > 0) scene_count = list(e)%integer_value
         if (file_count /= scene_count) then
            call mismatch(prefix, name, integer_text(int(file_count)), integer_text(int(scene_count)), why, stat, errmsg)
            return
         end if
         do e = 1, size(list)
            if (index(list(e)%name, trim(groups(k))//'.') /= 1 .or. list(e)%name == name) cycle
            call compare_entry(file, list(e), prefix, why, stat, errmsg)
            if (stat /= 0) return
         end do
      end do
   end subroutine compare_structure

   !> &beam planes (1 when not listed) and inertia_z (0: not given, the y plane's) of the
   !! file against the scene's: they make the state's unknowns and the z plane's stiffness.
   subroutine compare_planes(file, list, prefix, stat, errmsg)
      type(h5_reader), intent(in) :: file
      type(scene_entry), intent(in) :: list(:)
      character(len=*), intent(in) :: prefix
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      character(len=*), parameter :: why = '; the bending planes make the state''s unknowns (y, or y and z) and '// &
                                           'inertia_z the z plane''s stiffness: they must match'
      integer(int64) :: file_planes, scene_planes
      real(dp) :: file_inertia, scene_inertia
      integer :: e
      stat = 0
      errmsg = ''
      file_planes = 1
      scene_planes = 1
      file_inertia = 0
      scene_inertia = 0
      if (file%has_attr('/', 'beam.planes')) call file%attr_int64('/', 'beam.planes', file_planes, stat, errmsg)
      if (stat == 0 .and. file%has_attr('/', 'beam.inertia_z')) &
         call file%attr_real('/', 'beam.inertia_z', file_inertia, stat, errmsg)
      if (stat /= 0) then
         errmsg = prefix//trim(errmsg)
         return
      end if
      e = entry_index(list, 'beam.planes')
      if (e > 0) scene_planes = list(e)%integer_value
      e = entry_index(list, 'beam.inertia_z')
      if (e > 0) scene_inertia = list(e)%real_value
      if (file_planes /= scene_planes) then
         call mismatch(prefix, 'beam.planes', integer_text(int(file_planes)), integer_text(int(scene_planes)), why, &
                       stat, errmsg)
      else if (.not. same_bits(file_inertia, scene_inertia)) then
         call mismatch(prefix, 'beam.inertia_z', given(file_inertia), given(scene_inertia), why, stat, errmsg)
      end if
   contains
      !> The value, or 'not given' (0).
      function given(value) result(text)
         real(dp), intent(in) :: value
         character(len=:), allocatable :: text
         text = 'not given'
         if (value > 0) text = real_text(value)
      end function given
   end subroutine compare_planes

   !> The file's points (`path`: /contact/x, or /wear/x for a beam of two planes) against
   !! `x`, count and positions bitwise; `what` names one in the message.
   subroutine compare_points(file, path, what, x, prefix, stat, errmsg)
      type(h5_reader), intent(in) :: file
      character(len=*), intent(in) :: path, what
      real(dp), intent(in) :: x(:)
      character(len=*), intent(in) :: prefix
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      real(dp), allocatable :: in_file(:)
      integer :: k
      if (file%exists(path)) then
         call file%read_reals(path, in_file, stat, errmsg)
         if (stat /= 0) then
            errmsg = prefix//trim(errmsg)
            return
         end if
      else
         allocate (in_file(0))
         stat = 0
         errmsg = ''
      end if
      if (size(in_file) /= size(x)) then
         call mismatch(prefix, what//'s', integer_text(size(in_file)), integer_text(size(x)), model_why, stat, errmsg)
      else if (.not. all(same_bits(in_file, x))) then
         k = findloc(same_bits(in_file, x), .false., dim=1)
         call mismatch(prefix, what//' '//integer_text(k)//' x', real_text(in_file(k)), real_text(x(k)), model_why, &
                       stat, errmsg)
      end if
   end subroutine compare_points

   !> Are the obstacles' walls in the cross-section of a beam of two planes those of the
   !! file (every obstacle's place, kind of wall, size, centre, orientation and level, as
   !! listed, bitwise)? Then its state needs no check against them.
   logical function same_walls(file, list)
      type(h5_reader), intent(in) :: file
      type(scene_entry), intent(in) :: list(:)
      character(len=*), parameter :: walls(11) = [character(len=11) :: 'side', 'x_from', 'x_to', 'level_from', &
                                                  'level_to', 'shape', 'sides', 'orientation', 'radius', 'center_y', &
                                                  'center_z']
      integer :: e, k, stat
      character(len=1024) :: errmsg
      ! obstacles.count (the scene must list it) and every wall entry, each compared as
      ! `compare_entry` compares it, its message unused
      same_walls = .false.
      if (entry_index(list, 'obstacles.count') == 0) return
      do e = 1, size(list)
         k = index(list(e)%name, '(')
         if (list(e)%name /= 'obstacles.count') then
            if (index(list(e)%name, 'obstacles.') /= 1 .or. k == 0) cycle
            if (.not. any(list(e)%name(11:k - 1) == walls)) cycle
         end if
         if (.not. file%has_attr('/', trim(list(e)%name))) return
         call compare_entry(file, list(e), '', '', stat, errmsg)
         if (stat /= 0) return
      end do
      same_walls = .true.
   end function same_walls

   !> The compliant stops of the file against the scene's (`check_compatible`).
   subroutine compare_stops(file, scene, list, prefix, stat, errmsg)
      type(h5_reader), intent(in) :: file
      type(scene_type), intent(in) :: scene
      type(scene_entry), intent(in) :: list(:)
      character(len=*), intent(in) :: prefix
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      character(len=*), parameter :: compared(7) = [character(len=10) :: 'side', 'x_from', 'x_to', &
                                                     'level_from', 'level_to', 'stiffness', 'exponent']
      character(len=*), parameter :: hole_items(6) = [character(len=11) :: 'shape', 'sides', 'orientation', &
                                                      'radius', 'center_y', 'center_z']
      character(len=:), allocatable :: item
      integer(int64) :: file_count
      real(dp) :: file_stiffness
      logical :: file_compliant, scene_compliant
      integer :: i, k, e
      call file%attr_int64('/', 'obstacles.count', file_count, stat, errmsg)
      if (stat /= 0) then
         errmsg = prefix//trim(errmsg)
         return
      end if
      do i = 1, max(int(file_count), size(scene%obstacles))
         item = '('//integer_text(i)//')'
         file_compliant = .false.
         if (i <= file_count) then
            call file%attr_real('/', 'obstacles.stiffness'//item, file_stiffness, stat, errmsg)
            if (stat /= 0) then
               errmsg = prefix//trim(errmsg)
               return
            end if
            file_compliant = file_stiffness > 0
         end if
         scene_compliant = .false.
         if (i <= size(scene%obstacles)) scene_compliant = scene%obstacles(i)%stiffness > 0
         if (.not. (file_compliant .or. scene_compliant)) cycle
         if (i > file_count .or. i > size(scene%obstacles)) then
            call mismatch(prefix, 'obstacles.count', integer_text(int(file_count)), &
                          integer_text(size(scene%obstacles)), '; obstacle '//integer_text(i)// &
                          ' is a compliant stop in '//trim(merge('the file  ', 'this scene', i <= file_count))// &
                          stops_why, stat, errmsg)
            return
         end if
         do k = 1, size(compared) + 1
            ! the profile's file name too when the scene has one (files from before
            ! profiles have no such attribute, and no profile)
            if (k > size(compared)) then
               if (len_trim(scene%obstacles(i)%profile) == 0) exit
            end if
            e = entry_index(list, 'obstacles.'//trim(merge(compared(min(k, size(compared))), 'profile   ', &
                                                           k <= size(compared)))//item)
            call compare_entry(file, list(e), prefix, stops_why, stat, errmsg)
            if (stat /= 0) return
         end do
         ! a compliant hole of a beam of two planes (listed when the scene gives it): its
         ! wall is its shape, size, centre and orientation
         do k = 1, size(hole_items)
            e = entry_index(list, 'obstacles.'//trim(hole_items(k))//item)
            if (e == 0) cycle
            call compare_entry(file, list(e), prefix, stops_why, stat, errmsg)
            if (stat /= 0) return
         end do
      end do
   end subroutine compare_stops

   !> Compare the root attribute of `item`'s name in `file` with `item` (reals bitwise).
   !! stat = stat_failure with the mismatch message (`mismatch`, ending with `why`), or with the
   !! reader's message prefixed by `prefix`.
   subroutine compare_entry(file, item, prefix, why, stat, errmsg)
      type(h5_reader), intent(in) :: file
      type(scene_entry), intent(in) :: item
      character(len=*), intent(in) :: prefix, why
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      character(len=:), allocatable :: text
      real(dp) :: value
      integer(int64) :: number
      select case (item%kind)
      case ('real')
         call file%attr_real('/', trim(item%name), value, stat, errmsg)
         if (stat == 0 .and. .not. same_bits(value, item%real_value)) &
            call mismatch(prefix, trim(item%name), real_text(value), real_text(item%real_value), why, stat, errmsg)
      case ('integer')
         call file%attr_int64('/', trim(item%name), number, stat, errmsg)
         if (stat == 0 .and. number /= item%integer_value) &
            call mismatch(prefix, trim(item%name), integer_text(int(number)), integer_text(item%integer_value), why, &
                          stat, errmsg)
      case default
         call file%attr_string('/', trim(item%name), text, stat, errmsg)
         if (stat == 0 .and. text /= trim(item%string_value)) &
            call mismatch(prefix, trim(item%name), ''''//text//'''', ''''//trim(item%string_value)//'''', why, &
                          stat, errmsg)
      end select
      if (stat /= 0 .and. index(errmsg, prefix) /= 1) errmsg = prefix//trim(errmsg)
   end subroutine compare_entry

   !> stat = stat_failure and the message 'PREFIX NAME is IN_FILE in the file and IN_SCENE in this
   !! scene WHY'.
   subroutine mismatch(prefix, name, in_file, in_scene, why, stat, errmsg)
      character(len=*), intent(in) :: prefix, name, in_file, in_scene, why
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      stat = stat_failure
      errmsg = prefix//name//' is '//in_file//' in the file and '//in_scene//' in this scene'//why
   end subroutine mismatch
end module vibrobeam_restart_check
