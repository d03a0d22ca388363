!> A parameter sweep resolved against its scene (&sweep, docs/sweeps.md): `resolve_sweep`
!! checks the settings as given, resolves the parameters and their values
!! (`vibrobeam_sweep_axis`) and checks every point: its scene must be valid, hold as many
!! contact points as the first, and its windows at least one step (a sweep of periodic
!! orbits or branches, &analysis kind = 'periodic': `periodic_rules`). The points, their
!! order and each point's scene and windows are `vibrobeam_sweep_points`'; the settings
!! and points are taken from here by the modules that run a sweep.
module vibrobeam_sweep_settings
   use vibrobeam_status, only: stat_failure
   use vibrobeam_kinds, only: dp, int64
   use vibrobeam_text, only: real_text, integer_text
   use vibrobeam_scene, only: scene_type, scene_variables, structure_of
   use vibrobeam_scene_rules, only: validate_scene
   use vibrobeam_namelist_schema, only: namelist_variable, variable_index, choices_text
   use vibrobeam_model, only: beam_model, build_model
   use vibrobeam_contact_set, only: contact_set
   use vibrobeam_circle_set, only: circle_set
   use vibrobeam_obstacles, only: build_contact_points, build_circle_points
   use vibrobeam_sweep_axis, only: sweep_axis, resolve_axis
   use vibrobeam_continuation_axis, only: resolve_continuation, continues
   use vibrobeam_sweep_points, only: sweep_settings, sweep_point, sweep_points, point_scene, point_windows, &
      point_label, max_settle_windows, max_sweep_points, task_count
   implicit none
   private
   public :: resolve_sweep
   ! the sweep's settings and points, for the modules that run a sweep
   public :: sweep_settings, sweep_axis, sweep_point, sweep_points, point_scene, point_windows
   public :: max_settle_windows, max_sweep_points, task_count

contains

   !> Resolve the parameters against the scene's inputs (`scene_variables`), build the
   !! values, and check every point: its scene must be valid, hold as many contact points
   !! as the first, and its windows at least one step. stat = stat_failure with a message naming
   !! &sweep and the value otherwise.
   subroutine resolve_sweep(settings, scene, stat, errmsg)
      type(sweep_settings), intent(inout) :: settings
      type(scene_type), intent(in) :: scene
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      stat = 0
      errmsg = ''
      if (scene%analysis%kind /= 'dynamics' .and. scene%analysis%kind /= 'periodic') then
         stat = stat_failure
         errmsg = '&sweep needs &analysis kind = ''dynamics'' or ''periodic'' (kind = '''// &
                  trim(scene%analysis%kind)//''')'
         return
      end if
      call check_keyword('mode', settings%mode, stat, errmsg)
      if (stat == 0) call check_keyword('spacing', settings%axis(1)%spacing, stat, errmsg)
      if (stat == 0) call check_keyword('spacing2', settings%axis(2)%spacing, stat, errmsg)
      if (stat == 0) call resolve_axes(settings, scene, stat, errmsg)
      if (stat == 0) then
         if (scene%analysis%kind == 'periodic') then
            call periodic_rules(settings, scene, stat, errmsg)
         else
            call check_rules(settings, scene, stat, errmsg)
         end if
      end if
      if (stat == 0) call check_count(settings, stat, errmsg)
      if (stat == 0) call check_points(settings, scene, stat, errmsg)
   end subroutine resolve_sweep

   !> A keyword of &sweep against the choices of its row in `scene_variables`.
   subroutine check_keyword(name, value, stat, errmsg)
      character(len=*), intent(in) :: name, value
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      type(namelist_variable), allocatable :: table(:)
      type(namelist_variable) :: variable
      stat = 0
      errmsg = ''
      allocate (table, source=scene_variables())
      variable = table(variable_index(table, 'sweep', name))
      if (index('|'//trim(variable%choices)//'|', '|'//trim(value)//'|') > 0 .and. len_trim(value) > 0) return
      stat = stat_failure
      errmsg = '&sweep '//name//' = '''//trim(value)//''' is not one of '//choices_text(variable)
   end subroutine check_keyword

   !> Resolve parameter and, when it is named, parameter2 (which must differ).
   subroutine resolve_axes(settings, scene, stat, errmsg)
      type(sweep_settings), intent(inout) :: settings
      type(scene_type), intent(in) :: scene
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      stat = 0
      errmsg = ''
      call resolve_axis(settings%axis(1), 1, scene, stat, errmsg)
      if (stat /= 0) return
      if (len_trim(settings%axis(2)%parameter) == 0) then
         if (allocated(settings%axis(2)%given_values) .or. settings%axis(2)%range_given) then
            stat = stat_failure
            errmsg = '&sweep values2/from2/to2 are given but parameter2 is not: name the second parameter'
            return
         end if
         allocate (settings%axis(2)%values(0))
         return
      end if
      call resolve_axis(settings%axis(2), 2, scene, stat, errmsg)
      if (stat /= 0) return
      if (settings%axis(2)%parameter == settings%axis(1)%parameter) then
         stat = stat_failure
         errmsg = '&sweep parameter2 = '''//trim(settings%axis(2)%parameter)//''' is parameter itself: '// &
                  'a map needs two different inputs'
      end if
   end subroutine resolve_axes

   !> The rules between the settings, the first broken one reported: a continuation
   !! neither varies dt nor carries a reduced model's state; the measurement window is
   !! given, each window once.
   subroutine check_rules(settings, scene, stat, errmsg)
      type(sweep_settings), intent(in) :: settings
      type(scene_type), intent(in) :: scene
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      stat = stat_failure
      if (settings%mode /= 'independent' .and. trim(settings%axis(1)%group)//'.'//trim(settings%axis(1)%name) == 'time.dt') then
         errmsg = '&sweep parameter = ''time.dt'' with mode = '''//trim(settings%mode)//''': a continuation '// &
                  'carries the state from one time step to another; use mode = ''independent'''
      else if (settings%mode /= 'independent' .and. scene%mesh%reduction /= 'none') then
         ! a continuation point starts from the previous point's state; with a reduced model
         ! that state is in reduced coordinates, whose basis (the cut-off, the modes) may
         ! change with the parameter
         errmsg = '&sweep mode = '''//trim(settings%mode)//''' carries each point''s state to the next, '// &
                  'which a reduced model (&mesh reduction = '''//trim(scene%mesh%reduction)//''') cannot do: '// &
                  'use mode = ''independent'' or reduction = ''none'''
      else if (settings%measure <= 0 .and. settings%measure_periods <= 0) then
         errmsg = '&sweep: give the measurement window, measure (s) or measure_periods (> 0)'
      else if (settings%measure > 0 .and. settings%measure_periods > 0) then
         errmsg = '&sweep measure = '//real_text(settings%measure)//' and measure_periods = '// &
                  real_text(settings%measure_periods)//' are both given: give one of them'
      else if (settings%settle > 0 .and. settings%settle_periods > 0) then
         errmsg = '&sweep settle = '//real_text(settings%settle)//' and settle_periods = '// &
                  real_text(settings%settle_periods)//' are both given: give one of them'
      else
         stat = 0
         errmsg = ''
      end if
   end subroutine check_rules

   !> A sweep of &analysis kind = 'periodic' (docs/sweeps.md, "Sweeps of periodic orbits
   !! and branches"): each point is the periodic analysis its scene asks for (an orbit,
   !! an autonomous orbit or a continued branch), run as a single run would run it, its
   !! result its own file. So: mode = 'independent' (a point starts from its scene's
   !! start, not from another point's state), keep_runs = .true. (the point files are
   !! the result), no time-marching window (settle, measure, their periods,
   !! steady_tolerance), poincare_samples = 'latest' (there are none), and a parameter
   !! other than the continuation's own.
   subroutine periodic_rules(settings, scene, stat, errmsg)
      type(sweep_settings), intent(in) :: settings
      type(scene_type), intent(in) :: scene
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      character(len=*), parameter :: kind = ' with &analysis kind = ''periodic'': '
      type(sweep_axis) :: continued
      real(dp) :: start
      integer :: a
      stat = stat_failure
      if (settings%mode /= 'independent') then
         errmsg = '&sweep mode = '''//trim(settings%mode)//''' is not available'//kind//'each point''s orbit '// &
                  'or branch starts from its own scene; use mode = ''independent'' (to follow an orbit in a '// &
                  'parameter, continue it: &periodic parameter)'
      else if (.not. settings%keep_runs) then
         errmsg = '&sweep keep_runs = .false. is not available'//kind//'each point''s orbit or branch is its '// &
                  'own result file; give keep_runs = .true.'
      else if (settings%settle > 0 .or. settings%measure > 0 .or. settings%settle_periods > 0 .or. &
               settings%measure_periods > 0) then
         errmsg = '&sweep settle = '//real_text(settings%settle)//' s, measure = '//real_text(settings%measure)// &
                  ' s, settle_periods = '//real_text(settings%settle_periods)//', measure_periods = '// &
                  real_text(settings%measure_periods)//': time-marching windows are not available'//kind// &
                  'give none (the transient before Newton''s start is &periodic''s)'
      else if (settings%steady_tolerance > 0) then
         errmsg = '&sweep steady_tolerance = '//real_text(settings%steady_tolerance)//' is not available'//kind// &
                  'give 0 (the default)'
      else if (settings%poincare_samples /= 'latest') then
         errmsg = '&sweep poincare_samples = '''//trim(settings%poincare_samples)//''' is not available'//kind// &
                  'a periodic analysis has no Poincare samples; give ''latest'' (the default)'
      else
         stat = 0
         errmsg = ''
         if (.not. continues(scene)) return
         call resolve_continuation(scene, continued, start, stat, errmsg)
         if (stat /= 0) return
         do a = 1, 2
            if (len_trim(settings%axis(a)%parameter) == 0) cycle
            ! (a frequency and its twin in Hz are one input)
            if (settings%axis(a)%group == continued%group .and. &
                radians(settings%axis(a)%name) == radians(continued%name) .and. &
                settings%axis(a)%index == continued%index) then
               stat = stat_failure
               errmsg = '&sweep parameter'//trim(merge('  ', '2 ', a == 1))//' = '''// &
                        trim(settings%axis(a)%parameter)//''' is the continuation''s own parameter (&periodic '// &
                        'parameter): sweep another input (each point is a branch in &periodic parameter)'
            end if
         end do
      end if
   end subroutine periodic_rules

   !> An input's name without the '_hz' of a frequency's twin in Hz.
   pure function radians(name) result(base)
      character(len=*), intent(in) :: name
      character(len=len(name)) :: base
      integer :: n
      base = name
      n = len_trim(name)
      if (n > 3) then
         if (name(n - 2:n) == '_hz') base = name(1:n - 3)
      end if
   end function radians

   !> At most max_sweep_points points (counted in 64 bits: 65536 x 65536 values make 2^32).
   subroutine check_count(settings, stat, errmsg)
      type(sweep_settings), intent(in) :: settings
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      character(len=:), allocatable :: counted
      integer(int64) :: total
      stat = 0
      errmsg = ''
      total = int(size(settings%axis(1)%values), int64)*max(1, size(settings%axis(2)%values))
      if (settings%mode == 'up-down') total = 2*total
      if (total <= max_sweep_points) return
      counted = '&sweep: '//integer_text(size(settings%axis(1)%values))//' values'
      if (len_trim(settings%axis(2)%parameter) > 0) &
         counted = counted//' x '//integer_text(size(settings%axis(2)%values))//' values2'
      if (settings%mode == 'up-down') counted = counted//' x 2 branches'
      stat = stat_failure
      errmsg = counted//' make '//real_text(real(total, dp))//' points; at most '//integer_text(max_sweep_points)
   end subroutine check_count

   !> Every point's scene valid, its windows at least a step, its contact points as many
   !! as the first point's. The model and the contact points change only with a
   !! parameter of &beam, &mesh or &obstacles: otherwise those of the first point serve
   !! every point.
   subroutine check_points(settings, scene, stat, errmsg)
      type(sweep_settings), intent(in) :: settings
      type(scene_type), intent(in) :: scene
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      type(sweep_point), allocatable :: points(:)
      type(scene_type) :: trial
      type(beam_model) :: model
      type(contact_set) :: contacts
      character(len=:), allocatable :: warnings
      integer(int64) :: settle_steps, measure_steps
      type(sweep_axis) :: axis
      real(dp) :: start
      type(circle_set) :: circles
      integer :: k, contact_count, point_count
      logical :: same_model, same_contacts
      stat = 0
      errmsg = ''
      allocate (points, source=sweep_points(settings))
      same_model = .not. any(settings%axis%group == 'beam' .or. settings%axis%group == 'mesh' .or. &
                             settings%axis%group == 'supports' .or. settings%axis%group == 'masses')
      same_contacts = same_model .and. .not. any(settings%axis%group == 'obstacles')
      contact_count = -1
      do k = 1, size(points)
         trial = point_scene(scene, settings, points(k))
         call validate_scene(trial, stat, errmsg)
         if (stat == 0 .and. trial%analysis%kind /= 'periodic') &
            call point_windows(settings, trial, settle_steps, measure_steps, stat, errmsg)
         if (stat == 0 .and. continues(trial)) call resolve_continuation(trial, axis, start, stat, errmsg)
         if (stat == 0 .and. (k == 1 .or. .not. same_model)) &
            call build_model(trial%mesh%basis, trial%mesh%elements, trial%beam%length, trial%beam%rho_s(), &
                             trial%beam%ei(), model, stat, errmsg, structure=structure_of(trial))
         if (stat == 0 .and. (k == 1 .or. .not. same_contacts)) then
            warnings = ''
            if (trial%beam%plane_count() == 2) then   ! the points of the cross-section's obstacles
               call build_circle_points(trial%obstacles, model, circles, warnings, stat, errmsg)
               point_count = circles%count
            else
               call build_contact_points(trial%obstacles, model, contacts, warnings, stat, errmsg)
               point_count = contacts%count
            end if
         end if
         if (stat == 0 .and. contact_count >= 0 .and. point_count /= contact_count) then
            stat = stat_failure
            errmsg = 'the point has '//integer_text(point_count)//' contact points and point 1 has '// &
                     integer_text(contact_count)//': a sweep keeps the same contact points (move obstacles '// &
                     'between nodes, not across them)'
         end if
         if (stat /= 0) then
            errmsg = '&sweep point '//integer_text(k)//' ('//point_label(settings, points(k))//'): '//trim(errmsg)
            return
         end if
         contact_count = point_count
      end do
   end subroutine check_points
end module vibrobeam_sweep_settings
