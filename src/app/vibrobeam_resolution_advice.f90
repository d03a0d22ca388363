!> The resolution advice that `vibrobeam --check` prints for the statistics of a dynamics
!! run with obstacles and of a sweep (docs/statistics.md, "Which statistics converge"):
!! which statistics the scene's dt and N can be trusted for, and which are properties of
!! the discretization that may only be compared at equal dt and N.
!!
!! The thresholds are those measured by the convergence study of the statistics
!! (studies/statistics_convergence/REPORT.md) on two forced rattling scenes: the
!! statistics of the first group changed by less than about two of their batch-means
!! standard errors from level to level once N >= 8 and dt gave 1494 (one scene) and 1812
!! (the other) steps per period of mode 1, and by 3 to 11 standard errors at half those
!! steps (747, 906); the second group changed by many standard errors at every level.
module vibrobeam_resolution_advice
   use vibrobeam_kinds, only: dp, pi
   use vibrobeam_text, only: integer_text
   use vibrobeam_scene, only: scene_type
   use vibrobeam_scene_structure, only: scene_frequencies
   implicit none
   private
   public :: resolution_advice_text, advice_time_step, elements_converged, steps_per_period_converged

   !> Elements from which the converging statistics agreed within two standard errors in
   !! the study (they did from N = 8 on; at N = 4 the power input was 2.6 errors off).
   integer, parameter :: elements_converged = 8
   !> Steps per period of mode 1 (continuum, clamped-free) asked for: below the 1494 at which
   !! the study's statistics agreed within two standard errors and above the 906 at which
   !! they did not (REPORT.md, "Thresholds").
   real(dp), parameter :: steps_per_period_converged = 1400

contains

   !> The largest dt the advice asks for: steps_per_period_converged steps per period of
   !! the first flexible mode of the beam on its supports (continuum closed form, theory §7,
   !! or `scene_frequencies`); huge when the beam has none.
   real(dp) function advice_time_step(scene, mode)
      type(scene_type), intent(in) :: scene
      integer, intent(out), optional :: mode   !! that mode's number (1 unless rigid-body motions come first)
      real(dp) :: omega(3)
      integer :: first
      call scene_frequencies(scene, omega, first)
      advice_time_step = huge(1.0_dp)
      if (first > 0) advice_time_step = 2*pi/(omega(first)*steps_per_period_converged)
      if (present(mode)) mode = max(first, 1)
   end function advice_time_step

   !> The advice as lines of text, for a dynamics scene with at least one obstacle (empty
   !! otherwise: without contact the scheme is linear and converges at order 2 in dt).
   !! `what` names the run ('this run', 'point 3 of the sweep').
   function resolution_advice_text(scene, what) result(text)
      type(scene_type), intent(in) :: scene
      character(len=*), intent(in) :: what
      character(len=:), allocatable :: text
      real(dp) :: dt_wanted, steps
      logical :: time_ok, mesh_ok
      integer :: mode
      text = ''
      if (scene%analysis%kind /= 'dynamics' .or. size(scene%obstacles) == 0) return
      dt_wanted = advice_time_step(scene, mode)
      steps = steps_per_period_converged*dt_wanted/scene%time%dt
      time_ok = scene%time%dt <= dt_wanted
      mesh_ok = scene%mesh%elements >= elements_converged
      text = 'resolution advice for the statistics (docs/statistics.md, "Which statistics converge"):'// &
             new_line('a')
      text = text//'  converge to about 2 standard errors with dt <= '//g(dt_wanted)//' s ('// &
             integer_text(nint(steps_per_period_converged))//' steps per period of mode '//integer_text(mode)// &
             ') and elements >= '// &
             integer_text(elements_converged)//': RMS tip displacement, episode rate, impulse per episode, '// &
             'contact force, power input and dissipated in all, dominant frequency'//new_line('a')
      text = text//'  '//what//': dt = '//g(scene%time%dt)//' s ('//integer_text(int(steps))// &
             ' steps per period of mode '//integer_text(mode)//'), elements = '//integer_text(scene%mesh%elements)//': '
      if (time_ok .and. mesh_ok) then
         text = text//'resolved'
      else
         text = text//'not resolved:'
         if (.not. time_ok) text = text//' take dt <= '//g(dt_wanted)//' s'
         if (.not. (time_ok .or. mesh_ok)) text = text//' and'
         if (.not. mesh_ok) text = text//' elements >= '//integer_text(elements_converged)
      end if
      text = text//new_line('a')
      text = text//'  properties of dt and N (compare only at equal dt and N): impact rate and contact fraction '// &
             '(micro-impacts per episode multiply as dt and h shrink), RMS tip velocity and power dissipated by '// &
             'damping (high modes the impacts excite)'
      if (scene%impact%restitution < 1 .and. (scene%beam%rayleigh_mass > 0 .or. scene%beam%rayleigh_stiffness > 0)) &
         text = text//'; the split of the dissipated power between the stops (e < 1) and damping'
      text = text//new_line('a')
   end function resolution_advice_text

   !> A positive number rounded down to 3 significant digits, as 'd.dde<exponent>' (2.58e-5,
   !! 1.4e3 is '1.40e3'): a dt the advice asks for is then never above the threshold.
   function g(value) result(text)
      real(dp), intent(in) :: value
      character(len=:), allocatable :: text
      character(len=32) :: buffer
      integer :: exponent
      real(dp) :: mantissa
      if (.not. value > 0) then
         text = '0'
         return
      end if
      exponent = floor(log10(value))
      mantissa = floor(value/10.0_dp**exponent*100*(1 + 4*epsilon(1.0_dp)))/100.0_dp
      if (mantissa >= 10) then
         mantissa = mantissa/10
         exponent = exponent + 1
      end if
      write (buffer, '(f4.2)') mantissa
      text = trim(buffer)//'e'//integer_text(exponent)
   end function g
end module vibrobeam_resolution_advice
