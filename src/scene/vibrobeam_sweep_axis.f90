!> One axis of a parameter sweep (&sweep parameter or parameter2, docs/sweeps.md, "The
!! parameter"): the input it varies, as written ('group.variable' or
!! 'group.variable(i)'), resolved against the scene's inputs (`scene_variables`), and its
!! values (given one by one, or a range from, to, count with linear or log spacing),
!! each inside the variable's hard range.
module vibrobeam_sweep_axis
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use vibrobeam_status, only: stat_failure
   use vibrobeam_kinds, only: dp
   use vibrobeam_text, only: real_text, integer_text
   use vibrobeam_scene, only: scene_type, scene_variables, parameter_length, keyword_length
   use vibrobeam_namelist_schema, only: namelist_variable, kind_real, range_text
   use vibrobeam_namelist_tokens, only: lowercase
   use vibrobeam_scene_values, only: real_input
   implicit none
   private
   public :: sweep_axis, resolve_axis, resolve_name, check_range

   !> One axis: the parameter as written, what it names, and its values.
   type :: sweep_axis
      character(len=parameter_length) :: parameter = ''   !! 'group.variable' or 'group.variable(i)', lower case
      character(len=16) :: group = ''
      character(len=32) :: name = ''
      integer :: index = 1                  !! array element (1 for a scalar)
      character(len=16) :: unit = ''
      ! as given
      real(dp), allocatable :: given_values(:)
      logical :: range_given = .false.      !! from, to (and count) given
      real(dp) :: from = 0, to = 0
      integer :: count = 0
      character(len=keyword_length) :: spacing = 'linear'
      ! resolved
      real(dp), allocatable :: values(:)    !! in the order given (a range: from .. to)
   end type sweep_axis

contains

   !> Name, index and values of axis `a` (1: parameter, 2: parameter2) of a sweep of
   !! `scene`. stat = stat_failure with a message naming &sweep, the parameter and what is allowed.
   subroutine resolve_axis(axis, a, scene, stat, errmsg)
      type(sweep_axis), intent(inout) :: axis
      integer, intent(in) :: a
      type(scene_type), intent(in) :: scene
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      type(namelist_variable) :: variable
      character(len=:), allocatable :: label, suffix
      suffix = merge('  ', '2 ', a == 1)
      label = '&sweep parameter'//trim(suffix)//' = '''//trim(axis%parameter)//''''
      call resolve_name(axis, label, scene, variable, stat, errmsg)
      if (stat /= 0) return
      call axis_values(axis, trim(suffix), label, stat, errmsg)
      if (stat /= 0) return
      call check_range(axis, variable, label, stat, errmsg)
   end subroutine resolve_axis

   !> Group, name, element and unit of axis%parameter, an input of `scene` a sweep may
   !! vary (`variable`: its row); `label` starts each message ('&sweep parameter =
   !! ''...''', or a continuation's '&periodic parameter = ''...''').
   subroutine resolve_name(axis, label, scene, variable, stat, errmsg)
      type(sweep_axis), intent(inout) :: axis
      character(len=*), intent(in) :: label
      type(scene_type), intent(in) :: scene
      type(namelist_variable), intent(out) :: variable
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      real(dp) :: value
      logical :: found, element_given
      call parse_parameter(axis, label, element_given, stat, errmsg)
      if (stat /= 0) return
      call sweepable_variable(axis, label, element_given, variable, stat, errmsg)
      if (stat /= 0) return
      call used_by_scene(axis, label, scene, stat, errmsg)
      if (stat /= 0) return
      call real_input(scene, axis%group, axis%name, axis%index, value, found)
      if (.not. found) then
         stat = stat_failure
         if (axis%group == 'obstacles') then
            errmsg = label//': element '//integer_text(axis%index)//' is outside [1, '// &
                     integer_text(size(scene%obstacles))//'], the obstacles of &obstacles count'
         else
            errmsg = label//': element '//integer_text(axis%index)//' is outside [1, '// &
                     integer_text(size(scene%output%points))//'], the &output points given'
         end if
      end if
   end subroutine resolve_name

   !> 'group.variable' or 'group.variable(i)': axis%parameter in lower case, its group,
   !! name and element (`element_given`: written with '(i)').
   subroutine parse_parameter(axis, label, element_given, stat, errmsg)
      type(sweep_axis), intent(inout) :: axis
      character(len=*), intent(in) :: label
      logical, intent(out) :: element_given
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      character(len=:), allocatable :: text
      integer :: open, close, dot, ios
      stat = stat_failure
      element_given = .false.
      text = lowercase(trim(axis%parameter))
      if (len(text) == 0) then
         errmsg = '&sweep parameter is missing: name the input to vary, e.g. parameter = ''load.base_frequency'''
         return
      end if
      axis%parameter = text
      dot = index(text, '.')
      open = index(text, '(')
      close = index(text, ')')
      if (dot < 2) then
         errmsg = label//' is not of the form ''group.variable'' or ''group.variable(i)'''
         return
      end if
      axis%index = 1
      element_given = open > 0
      if (open > 0) then
         if (close /= len(text) .or. close < open + 2) then
            errmsg = label//': write the element as ''group.variable(i)'''
            return
         end if
         read (text(open + 1:close - 1), *, iostat=ios) axis%index
         if (ios /= 0 .or. verify(text(open + 1:close - 1), '0123456789') /= 0) then
            errmsg = label//': the element '''//text(open + 1:close - 1)//''' is not a whole number'
            return
         end if
         axis%name = text(dot + 1:open - 1)
      else
         axis%name = text(dot + 1:)
      end if
      axis%group = text(1:dot - 1)
      stat = 0
      errmsg = ''
   end subroutine parse_parameter

   !> The row of `scene_variables` that axis%group and axis%name name, when a sweep may
   !! vary it: a real input of the scene, not one the sweep sets itself (t_end,
   !! measure_from) nor wall-clock time (checkpoint_seconds), with an element exactly when
   !! it is an array. Sets axis%unit.
   subroutine sweepable_variable(axis, label, element_given, variable, stat, errmsg)
      type(sweep_axis), intent(inout) :: axis
      character(len=*), intent(in) :: label
      logical, intent(in) :: element_given
      type(namelist_variable), intent(out) :: variable
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      type(namelist_variable), allocatable :: table(:)
      integer :: row, k
      stat = stat_failure
      allocate (table, source=scene_variables())
      row = 0
      do k = 1, size(table)
         if (table(k)%group == axis%group .and. table(k)%name == axis%name) row = k
      end do
      if (row == 0 .or. axis%group == 'sweep') then
         errmsg = label//' is not an input of vibrobeam (docs/input.md lists them)'
         return
      end if
      variable = table(row)
      axis%unit = variable%unit
      if (variable%kind /= kind_real) then
         errmsg = label//' is not a real input: only real values can be swept'
         return
      end if
      select case (trim(axis%group)//'.'//trim(axis%name))
      case ('time.t_end', 'output.measure_from')
         errmsg = label//' is set by the sweep itself (settle and measure windows)'
         return
      case ('output.checkpoint_seconds')
         errmsg = label//' is wall-clock time, not a property of the scene'
         return
      end select
      if (axis%group == 'periodic') then
         errmsg = label//' belongs to &periodic, the settings of the periodic analysis itself, which neither a '// &
                  'sweep (its points run the analysis these settings describe) nor a continuation (its points are orbits '// &
                  'of the scene) varies'
         return
      end if
      if (variable%extent > 0 .and. .not. element_given) then
         errmsg = label//' is an array: name one element, '''//trim(axis%group)//'.'//trim(axis%name)//'(1)'''
         return
      else if (variable%extent == 0 .and. element_given) then
         errmsg = label//': '//trim(axis%name)//' is not an array'
         return
      end if
      stat = 0
      errmsg = ''
   end subroutine sweepable_variable

   !> stat = stat_failure when the scene's rules replace the value the sweep would set, so that every
   !! point would run the same scene: k2 of a beam given by E, rho, S and I (k2 is then
   !! EI/(rho S); docs/input.md, "&beam"), and k2, E, rho, S, I of a beam given by its
   !! &sections.
   subroutine used_by_scene(axis, label, scene, stat, errmsg)
      type(sweep_axis), intent(in) :: axis
      character(len=*), intent(in) :: label
      type(scene_type), intent(in) :: scene
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      character(len=*), parameter :: beam_data(5) = [character(len=14) :: 'k2', 'youngs_modulus', 'density', 'area', &
                                                     'inertia']
      stat = 0
      errmsg = ''
      if (axis%group == 'beam' .and. scene%beam%sectioned() .and. any(axis%name == beam_data)) then
         stat = stat_failure
         errmsg = label//' would change nothing: the beam is given by its &sections, which cover it whole; sweep '// &
                  'a section''s value (sections.'//trim(axis%name)//'(i))'
         return
      end if
      if (axis%group == 'beam' .and. axis%name == 'k2' .and. scene%beam%physical()) then
         stat = stat_failure
         errmsg = label//' would change nothing: youngs_modulus, density, area and inertia are given, so '// &
                  'k2 = EI/(rho S); sweep one of them, or give the beam by k2 alone'
      end if
   end subroutine used_by_scene

   !> axis%values: the values given, or the range from .. to of count values (linear or
   !! log spacing; the ends exact). `suffix`: '' or '2' (the names of axis 2's variables).
   subroutine axis_values(axis, suffix, label, stat, errmsg)
      type(sweep_axis), intent(inout) :: axis
      character(len=*), intent(in) :: suffix, label
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer :: k
      stat = stat_failure
      if (allocated(axis%given_values) .and. axis%range_given) then
         errmsg = '&sweep values'//suffix//' and from'//suffix//'/to'//suffix//' are both given: give the values or a range'
         return
      end if
      if (allocated(axis%given_values)) then
         if (size(axis%given_values) == 0) deallocate (axis%given_values)
      end if
      if (allocated(axis%given_values)) then
         axis%values = axis%given_values
      else if (axis%range_given) then
         if (axis%count < 1) then
            errmsg = '&sweep count'//suffix//' is missing: how many values from'//suffix//' to to'//suffix// &
                     ' (1: from alone)'
            return
         end if
         if (axis%spacing == 'log' .and. (axis%from <= 0 .or. axis%to <= 0)) then
            errmsg = '&sweep spacing'//suffix//' = ''log'' with from'//suffix//' = '//real_text(axis%from)// &
                     ' and to'//suffix//' = '//real_text(axis%to)//': both must be > 0'
            return
         end if
         allocate (axis%values(axis%count))
         do k = 1, axis%count
            if (axis%count == 1) then
               axis%values(k) = axis%from
            else if (k == axis%count) then
               axis%values(k) = axis%to
            else if (axis%spacing == 'log') then
               axis%values(k) = axis%from*(axis%to/axis%from)**(real(k - 1, dp)/(axis%count - 1))
            else
               axis%values(k) = axis%from + (k - 1)*((axis%to - axis%from)/(axis%count - 1))
            end if
         end do
      else
         errmsg = '&sweep: give values'//suffix//' or from'//suffix//', to'//suffix//' and count'//suffix// &
                  ' for '//label(8:)
         return
      end if
      stat = 0
      errmsg = ''
   end subroutine axis_values

   !> Each value of the axis (axis%values) inside the hard range of its `variable`.
   subroutine check_range(axis, variable, label, stat, errmsg)
      type(sweep_axis), intent(in) :: axis
      type(namelist_variable), intent(in) :: variable
      character(len=*), intent(in) :: label
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      real(dp) :: value
      integer :: k
      stat = 0
      errmsg = ''
      do k = 1, size(axis%values)
         value = axis%values(k)
         if (.not. ieee_is_finite(value) .or. value < variable%lowest .or. value > variable%highest .or. &
             (abs(value) > 0 .and. abs(value) < variable%smallest_nonzero)) then
            stat = stat_failure
            errmsg = label//': value '//integer_text(k)//' = '//real_text(value)//' is outside '// &
                     range_text(variable)//', the range of &'//trim(axis%group)//' '//trim(axis%name)
            return
         end if
      end do
   end subroutine check_range
end module vibrobeam_sweep_axis
