!> What a periodic-orbit analysis does, as the input gives it (&periodic, docs/input.md;
!! &analysis kind = 'periodic', docs/method.md "Periodic orbits by shooting"): how many
!! forcing periods the orbit spans, how a period is cut into steps, where Newton's method
!! starts, when it stops and how the monodromy is computed; each variable declared once in
!! `visit_periodic` (`vibrobeam_schema_visitor`).
!!
!! The group belongs to kind = 'periodic': `visit_scene` visits it only in a scene of that
!! kind (so results of the other kinds do not list it), and the table of every variable
!! always holds it.
module vibrobeam_periodic_settings
   use vibrobeam_kinds, only: dp, pi
   use vibrobeam_text, only: real_text
   use vibrobeam_schema_visitor, only: schema_visitor, real_row, integer_row, keyword_row, text_row, logical_row, &
      keyword_length, unset
   use vibrobeam_loads, only: load_settings
   implicit none
   private
   public :: periodic_settings, visit_periodic, forcing_frequency, period_step, whole_step_tolerance
   public :: continuation_parameter_length

   !> Longest &periodic parameter name ('group.variable(i)', as &sweep parameter).
   integer, parameter :: continuation_parameter_length = 64

   !> Largest relative distance of T/dt from a whole number that &time dt may leave (the
   !! forcing period T = 2 pi/Omega): the phase of the forcing then slips by at most
   !! 2 pi 1e-9 per period, below the default Newton tolerance's effect on the orbit.
   real(dp), parameter :: whole_step_tolerance = 1e-9_dp

   !> &periodic.
   type :: periodic_settings
      integer :: period_multiple = 1              !! k: the orbit spans k forcing periods
      integer :: steps_per_period = 0             !! steps per forcing period; 0: &time dt, which must divide it
      integer :: transient_periods = 0            !! forcing periods stepped from the start before Newton
      real(dp) :: tolerance = 1e-9_dp             !! relative residual of the period map (energy norm)
      integer :: max_iterations = 30              !! Newton iterations before the analysis fails
      character(len=keyword_length) :: monodromy = 'auto'   !! 'auto' | 'linearised' | 'differences'
      ! continuation (docs/method.md, "Continuation of periodic orbits"); parameter '': none
      character(len=continuation_parameter_length) :: parameter = ''   !! 'group.variable(i)' continued in
      real(dp) :: step = 0                         !! first arclength step, in the parameter's unit (its sign: the direction)
      real(dp) :: parameter_min = unset            !! the branch ends below it (unset: no bound)
      real(dp) :: parameter_max = unset            !! the branch ends above it (unset: no bound)
      integer :: max_points = 100                  !! most points of the branch
      !> at the branch's first located period doubling, switch to the orbits of twice the
      !! period and continue them too (docs/method.md, "Branch switching at a period doubling")
      logical :: switch_branch = .false.
      ! autonomous orbits (docs/method.md, "Autonomous periodic orbits"): no forcing, the
      ! period an unknown, steps_per_period steps of dt = T/steps_per_period each
      logical :: autonomous = .false.              !! free vibration: the period T is an unknown
      real(dp) :: period = unset                   !! the guess of T (s), required with autonomous
      !> the tip's displacement at the orbit's start (m), which picks the member of the
      !! conservative scene's family of orbits (unset: the start's own tip displacement)
      real(dp) :: tip_amplitude = unset
   end type periodic_settings

contains

   !> Every variable of &periodic, once (docs/input.md, "&periodic").
   subroutine visit_periodic(periodic, visitor)
      type(periodic_settings), intent(inout) :: periodic
      class(schema_visitor), intent(inout) :: visitor
      call visitor%variable(integer_row('periodic', 'period_multiple', 1, 1000, &
                                        'the orbit spans this many forcing periods (k)'), periodic%period_multiple)
      call visitor%variable(integer_row('periodic', 'steps_per_period', 0, 1000000000, &
                                        'time steps per forcing period, dt = T/steps (0: &time dt, a whole '// &
                                        'fraction of T)'), periodic%steps_per_period)
      call visitor%variable(integer_row('periodic', 'transient_periods', 0, 1000000000, &
                                        'forcing periods stepped from the start before Newton''s method'), &
                            periodic%transient_periods)
      call visitor%variable(real_row('periodic', 'tolerance', '', 1e-15_dp, 1e-2_dp, &
                                     'Newton stops when the period map moves the state by less than this, '// &
                                     'relative (energy norm)'), periodic%tolerance)
      call visitor%variable(integer_row('periodic', 'max_iterations', 1, 10000, &
                                        'Newton iterations before the analysis fails'), periodic%max_iterations)
      call visitor%variable(keyword_row('periodic', 'monodromy', 'auto|linearised|differences', keyword_length, &
                                        'Jacobian of the period map: linearised steps or finite differences'), &
                            periodic%monodromy)
      call visitor%variable(text_row('periodic', 'parameter', continuation_parameter_length, &
                                     'continue the orbit in this input, ''group.variable'' as &sweep parameter '// &
                                     '('''': one orbit, no continuation)'), periodic%parameter)
      call visitor%variable(real_row('periodic', 'step', '', -1e30_dp, 1e30_dp, &
                                     'first continuation step, in the parameter''s unit; its sign is the '// &
                                     'direction'), periodic%step)
      call visitor%variable(real_row('periodic', 'parameter_min', '', -1e30_dp, 1e30_dp, &
                                     'the branch ends where the parameter goes below this', optional=.true.), &
                            periodic%parameter_min)
      call visitor%variable(real_row('periodic', 'parameter_max', '', -1e30_dp, 1e30_dp, &
                                     'the branch ends where the parameter goes above this', optional=.true.), &
                            periodic%parameter_max)
      call visitor%variable(integer_row('periodic', 'max_points', 2, 100000, &
                                        'most points of a continued branch'), periodic%max_points)
      call visitor%variable(logical_row('periodic', 'switch_branch', 'at the first located period doubling of '// &
                                        'the continued branch, switch to the orbits of twice the period and '// &
                                        'continue them too (needs parameter)'), periodic%switch_branch)
      call visitor%variable(logical_row('periodic', 'autonomous', 'free vibration without forcing: the period is '// &
                                        'an unknown, steps_per_period steps of dt = period/steps_per_period each'), &
                            periodic%autonomous)
      call visitor%variable(real_row('periodic', 'period', 's', 1e-15_dp, 1e12_dp, &
                                     'the guess of the autonomous orbit''s period (required with autonomous)', &
                                     optional=.true.), periodic%period)
      call visitor%variable(real_row('periodic', 'tip_amplitude', 'm', -1e6_dp, 1e6_dp, &
                                     'the tip''s displacement at the autonomous orbit''s start, where its velocity '// &
                                     'is 0 (none: the start''s own)', optional=.true.), periodic%tip_amplitude)
   end subroutine visit_periodic

   !> The one frequency of the harmonic loads of `load` (a load with a non-zero amplitude
   !! and a frequency > 0; constant loads may come with them), in `omega` (rad/s).
   !! `problem` is '' when there is one, else why not: no harmonic load, or two of
   !! different frequencies (relative difference above 1e-12).
   subroutine forcing_frequency(load, omega, problem)
      type(load_settings), intent(in) :: load
      real(dp), intent(out) :: omega
      character(len=:), allocatable, intent(out) :: problem
      real(dp) :: frequencies(3)
      logical :: harmonic(3)
      character(len=*), parameter :: names(3) = [character(len=21) :: 'base_frequency', 'point_frequency', &
                                                  'distributed_frequency']
      integer :: k, first
      frequencies = [load%base_frequency, load%point_frequency, load%distributed_frequency]
      harmonic = [abs(load%base_load_amplitude()) > 0 .and. load%base_frequency > 0, &
                  abs(load%point_force) > 0 .and. load%point_frequency > 0, &
                  abs(load%distributed) > 0 .and. load%distributed_frequency > 0]
      omega = 0
      problem = ''
      if (.not. any(harmonic)) then
         problem = 'needs a harmonic load (&load base_, point_ or distributed_ amplitude and frequency > 0), '// &
                   'whose period the orbit follows; free vibration (the period as an unknown) is not available yet'
         return
      end if
      first = findloc(harmonic, .true., dim=1)
      omega = frequencies(first)
      do k = first + 1, 3
         if (.not. harmonic(k)) cycle
         if (abs(frequencies(k) - omega) > 1e-12_dp*omega) then
            problem = 'needs the harmonic loads to share one frequency: &load '//trim(names(first))//' = '// &
                      real_text(omega)//' rad/s and '//trim(names(k))//' = '//real_text(frequencies(k))//' rad/s'
            omega = 0
            return
         end if
      end do
   end subroutine forcing_frequency

   !> The time step dt = T/steps_per_period of a forcing of frequency `omega` (rad/s), T = 2 pi/omega.
   pure real(dp) function period_step(omega, steps_per_period)
      real(dp), intent(in) :: omega
      integer, intent(in) :: steps_per_period
      period_step = 2*pi/omega/steps_per_period
   end function period_step
end module vibrobeam_periodic_settings
