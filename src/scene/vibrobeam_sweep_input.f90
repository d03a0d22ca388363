!> The &sweep group as written (docs/sweeps.md), each variable declared once in
!! `visit_sweep` (`vibrobeam_schema_visitor`). `vibrobeam_sweep_settings` turns it into
!! the sweep's axes, points and windows, checked against the scene.
module vibrobeam_sweep_input
   use vibrobeam_kinds, only: dp
   use vibrobeam_schema_visitor, only: schema_visitor, real_row, integer_row, keyword_row, text_row, logical_row, &
      keyword_length, unset_integer
   implicit none
   private
   public :: sweep_input, visit_sweep, max_sweep_values, parameter_length

   integer, parameter :: max_sweep_values = 1000  !! most explicit values of a sweep axis (&sweep values)
   integer, parameter :: parameter_length = 64    !! longest &sweep parameter name

   !> &sweep: two axes (the second optional), the order of the points, the windows.
   type :: sweep_input
      character(len=parameter_length) :: parameter = '', parameter2 = ''
      real(dp) :: values(max_sweep_values) = 0, values2(max_sweep_values) = 0
      real(dp) :: from = 0, to = 0, from2 = 0, to2 = 0
      integer :: count = unset_integer, count2 = unset_integer   !! unset: not given
      character(len=keyword_length) :: spacing = 'linear', spacing2 = 'linear'
      character(len=keyword_length) :: mode = 'independent'
      real(dp) :: settle = 0, measure = 0, settle_periods = 0, measure_periods = 0
      real(dp) :: steady_tolerance = 0
      logical :: keep_runs = .false.
      character(len=keyword_length) :: poincare_samples = 'latest'   !! 'latest' (256) | 'all' of a point's window
   end type sweep_input

contains

   !> Every variable of &sweep, once (docs/input.md, "&sweep"; docs/sweeps.md).
   subroutine visit_sweep(sweep, visitor)
      type(sweep_input), intent(inout) :: sweep
      class(schema_visitor), intent(inout) :: visitor
      call visitor%variable(text_row('sweep', 'parameter', parameter_length, &
                                     'the real input varied, ''group.variable'' or ''group.variable(i)'''), &
                            sweep%parameter)
      call visitor%variable(real_row('sweep', 'values', '', -1e30_dp, 1e30_dp, 'the parameter''s values', &
                                     extent=max_sweep_values), sweep%values)
      call visitor%variable(real_row('sweep', 'from', '', -1e30_dp, 1e30_dp, 'first value of a range'), sweep%from)
      call visitor%variable(real_row('sweep', 'to', '', -1e30_dp, 1e30_dp, 'last value of a range'), sweep%to)
      call visitor%variable(integer_row('sweep', 'count', 1, 100000, 'number of values from from to to', &
                                        optional=.true.), sweep%count)
      call visitor%variable(keyword_row('sweep', 'spacing', 'linear|log', keyword_length, &
                                        'values evenly spaced, or evenly spaced in the logarithm'), sweep%spacing)
      call visitor%variable(keyword_row('sweep', 'mode', 'independent|up|down|up-down', keyword_length, &
                                        'every point from the initial state, or a continuation up and/or down'), &
                            sweep%mode)
      call visitor%variable(text_row('sweep', 'parameter2', parameter_length, &
                                     'a second parameter: each of its values is one line of points (a map)'), &
                            sweep%parameter2)
      call visitor%variable(real_row('sweep', 'values2', '', -1e30_dp, 1e30_dp, 'the second parameter''s values', &
                                     extent=max_sweep_values), sweep%values2)
      call visitor%variable(real_row('sweep', 'from2', '', -1e30_dp, 1e30_dp, 'first value of the second range'), &
                            sweep%from2)
      call visitor%variable(real_row('sweep', 'to2', '', -1e30_dp, 1e30_dp, 'last value of the second range'), &
                            sweep%to2)
      call visitor%variable(integer_row('sweep', 'count2', 1, 100000, 'number of values of the second parameter', &
                                        optional=.true.), sweep%count2)
      call visitor%variable(keyword_row('sweep', 'spacing2', 'linear|log', keyword_length, &
                                        'spacing of the second parameter''s values'), sweep%spacing2)
      call visitor%variable(real_row('sweep', 'settle', 's', 0.0_dp, 1e12_dp, &
                                     'transient before the measurement window at each point'), sweep%settle)
      call visitor%variable(real_row('sweep', 'measure', 's', 0.0_dp, 1e12_dp, 'measurement window at each point'), &
                            sweep%measure)
      call visitor%variable(real_row('sweep', 'settle_periods', '', 0.0_dp, 1e9_dp, &
                                     'the transient in periods of the point''s forcing'), sweep%settle_periods)
      call visitor%variable(real_row('sweep', 'measure_periods', '', 0.0_dp, 1e9_dp, &
                                     'the window in periods of the point''s forcing'), sweep%measure_periods)
      call visitor%variable(real_row('sweep', 'steady_tolerance', '', 0.0_dp, 1.0_dp, &
                                     '> 0: measure window after window until two agree within this'), &
                            sweep%steady_tolerance)
      call visitor%variable(logical_row('sweep', 'keep_runs', 'also write each point''s full result file'), &
                            sweep%keep_runs)
      call visitor%variable(keyword_row('sweep', 'poincare_samples', 'latest|all', keyword_length, &
                                        'the Poincare samples of a point the sweep file keeps: the latest 256, or '// &
                                        'every one of its window'), sweep%poincare_samples)
   end subroutine visit_sweep
end module vibrobeam_sweep_input
