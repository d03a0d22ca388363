!> What a run writes, as the input gives it (&output, docs/input.md): the result file,
!! how often histories and fields are sampled, observation points, the statistics window,
!! checkpoints; each variable declared once in `visit_output` (`vibrobeam_schema_visitor`).
module vibrobeam_output_settings
   use vibrobeam_kinds, only: dp
   use vibrobeam_schema_visitor, only: schema_visitor, real_row, integer_row, keyword_row, text_row, logical_row, &
      unset, keyword_length, path_length
   implicit none
   private
   public :: output_settings, visit_output, max_points

   integer, parameter :: max_points = 64          !! most observation points (&output points)

   !> &output.
   type :: output_settings
      character(len=path_length) :: file = 'results/vibrobeam.h5'
      integer :: every = 10                   !! histories every `every` steps
      logical :: text = .true.
      logical :: progress = .false.
      integer :: field_every = 0              !! field snapshots every `field_every` steps (0: = every)
      real(dp), allocatable :: points(:)      !! observation points x (m), beside the tip
      real(dp) :: measure_from = 0            !! start of the statistics window (s)
      real(dp) :: checkpoint_seconds = 0      !! > 0: restartable checkpoint this often (wall s)
      real(dp) :: episode_gap = unset         !! impacts closer than this form one episode (s); unset: default
      character(len=keyword_length) :: poincare_load = 'auto'   !! whose phase times the Poincare samples
      !> the largest Lyapunov exponent of the discrete map over the statistics window (a
      !! tangent step per step: opt-in)
      logical :: lyapunov = .false.
   end type output_settings

contains

   !> Every variable of &output, once (docs/input.md, "&output"). `points` holds the
   !! observation points given (the reader gives it room for max_points first).
   subroutine visit_output(output, visitor)
      type(output_settings), intent(inout) :: output
      class(schema_visitor), intent(inout) :: visitor
      if (.not. allocated(output%points)) allocate (output%points(0))
      call visitor%variable(text_row('output', 'file', path_length, 'HDF5 result file'), output%file)
      call visitor%variable(integer_row('output', 'every', 1, huge(1), 'write the histories every this many steps'), &
                            output%every)
      call visitor%variable(logical_row('output', 'text', 'also write gnuplot-ready .dat files'), output%text)
      call visitor%variable(logical_row('output', 'progress', 'report progress on stderr even when it is not a '// &
                                        'terminal'), output%progress)
      call visitor%variable(integer_row('output', 'field_every', 0, huge(1), &
                                        'write the displacement field every this many steps (0: every)'), &
                            output%field_every)
      call visitor%variable(real_row('output', 'points', 'm', 0.0_dp, 1e6_dp, &
                                     'x positions of observation points', extent=max_points), output%points)
      call visitor%variable(real_row('output', 'measure_from', 's', 0.0_dp, 1e12_dp, &
                                     'start of the statistics window'), output%measure_from)
      call visitor%variable(real_row('output', 'checkpoint_seconds', 's', 0.0_dp, 1e9_dp, &
                                     'write a restartable checkpoint this often (wall-clock seconds; 0: at the end)'), &
                            output%checkpoint_seconds)
      call visitor%variable(real_row('output', 'episode_gap', 's', 1e-18_dp, 1e12_dp, &
                                     'impacts closer in time than this form one contact episode', optional=.true.), &
                            output%episode_gap)
      call visitor%variable(keyword_row('output', 'poincare_load', 'auto|base|point|distributed', keyword_length, &
                                        'the harmonic load whose phase times the Poincare samples'), &
                            output%poincare_load)
      call visitor%variable(logical_row('output', 'lyapunov', 'the largest Lyapunov exponent of the discrete map '// &
                                        'over the statistics window (a tangent step per step)'), output%lyapunov)
   end subroutine visit_output
end module vibrobeam_output_settings
