!> The backbone of a nonlinear normal mode: the autonomous orbit continued in its tip
!! amplitude (&periodic autonomous = .true., parameter = 'periodic.tip_amplitude';
!! docs/method.md, "Autonomous periodic orbits", "The backbone"), period against amplitude
!! (Peeters, Viguie, Serandour, Kerschen, Golinval, MSSP 23 (2009) 195-216).
!!
!! A natural-parameter continuation in A: the amplitude condition u_tip(x) = A already
!! picks one orbit of the conservative family, and a backbone is monotone in it (a stop
!! that hardens or softens the mode moves its period one way), so A itself parametrises
!! the branch and no arclength is needed. From the first orbit (`find_autonomous_orbit`
!! at the scene's tip_amplitude), each next point is A + ds, its (x, T) predicted by the
!! secant through the last two points (the first step: x scaled by the ratio of the
!! amplitudes, exact for a linear mode, T kept), corrected by the same Gauss-Newton with
!! A fixed. The step follows the forced continuation's rules (`vibrobeam_continuation`:
!! halved when a corrector fails or takes more than corrector_iterations, grown by
!! step_growth after an easy one, up to largest_step times the first, the branch given up
!! after max_halvings halvings) and the last one is shortened to land on parameter_min or
!! parameter_max, which ends the branch there. No bifurcations are looked for: a
!! conservative orbit's multipliers all lie on the unit circle, so the forced branch's
!! test functions (a multiplier through -1, a pair through the circle) change sign on
!! round-off, and a fold in A is not met by a monotone backbone.
module vibrobeam_backbone
   use vibrobeam_kinds, only: dp
   use vibrobeam_status, only: outcome_ok, outcome_failed, outcome_interrupted
   use vibrobeam_text, only: real_text, integer_text
   use vibrobeam_scene, only: scene_type
   use vibrobeam_schema_visitor, only: is_unset
   use vibrobeam_continuation_axis, only: resolve_continuation
   use vibrobeam_problem, only: run_problem
   use vibrobeam_periodic_analysis, only: periodic_orbit
   use vibrobeam_autonomous_orbit, only: find_autonomous_orbit
   use vibrobeam_continuation, only: continuation_branch, corrector_iterations, easy_iterations, step_growth, &
      largest_step, max_halvings
   use vibrobeam_branch_point, only: branch_point
   use vibrobeam_progress, only: progress_meter
   use vibrobeam_signals, only: interrupt_requested
   implicit none
   private
   public :: continue_backbone, trivial_pair_splitting

contains

   !> The backbone through the autonomous orbit of `scene` (&periodic parameter =
   !! 'periodic.tip_amplitude'; `prepared` its problem) in `branch`, as `continue_branch`
   !! gives a forced one: stat /= 0 (errmsg) for invalid continuation input or a stepper
   !! that cannot be made; a branch that ends early is branch%status = outcome_failed with
   !! the reason, its points kept. `meter` reports each point.
   subroutine continue_backbone(scene, prepared, branch, stat, errmsg, meter)
      type(scene_type), intent(in) :: scene
      type(run_problem), intent(in) :: prepared
      type(continuation_branch), intent(out) :: branch
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      type(progress_meter), intent(inout) :: meter
      type(scene_type) :: local
      type(periodic_orbit) :: orbit
      type(progress_meter) :: silent
      type(branch_point) :: point
      real(dp) :: start, ds, first_step, target, ratio, period
      real(dp), allocatable :: predicted(:)
      integer :: halvings, n
      logical :: at_end
      call resolve_continuation(scene, branch%axis, start, stat, errmsg)
      if (stat /= 0) return
      branch%backbone = .true.
      allocate (branch%points(0), branch%bifurcations(0))
      call silent%init(.false.)
      silent%enabled = .false.
      local = scene
      local%periodic%tip_amplitude = start
      call find_autonomous_orbit(local, prepared, orbit, stat, errmsg, silent)
      if (stat /= 0) return
      branch%monodromy = orbit%monodromy
      branch%first_iterations = orbit%iterations
      branch%orbit_steps = orbit%map%steps
      branch%steps_taken = orbit%map%steps_taken
      if (.not. orbit%converged .or. orbit%status /= outcome_ok) then
         branch%status = merge(outcome_interrupted, outcome_failed, orbit%status == outcome_interrupted)
         branch%failure = 'the first orbit, at '//trim(branch%axis%parameter)//' = '//real_text(start)//': '// &
                          trim(orbit%failure)
         return
      end if
      call set_point(orbit, start, 0.0_dp, point)
      branch%points = [point]
      call report()
      ! the correctors: Gauss-Newton from the predictor, given up as the forced corrector is
      local%periodic%max_iterations = min(scene%periodic%max_iterations, corrector_iterations)
      first_step = scene%periodic%step
      ds = first_step
      halvings = 0
      do while (size(branch%points) < scene%periodic%max_points)
         if (interrupt_requested()) then
            branch%status = outcome_interrupted
            exit
         end if
         n = size(branch%points)
         target = branch%points(n)%parameter + ds
         call clip_to_bound(target, at_end)
         if (.not. abs(target - branch%points(n)%parameter) > 0) exit   ! (the start on the bound)
         ! the predictor: the secant through the last two points, or the first scaled
         associate (last => branch%points(n))
            if (n >= 2) then
               ratio = (target - last%parameter)/(last%parameter - branch%points(n - 1)%parameter)
               predicted = last%x + ratio*(last%x - branch%points(n - 1)%x)
               period = last%period + ratio*(last%period - branch%points(n - 1)%period)
            else
               predicted = last%x*(target/last%parameter)
               period = last%period
            end if
            if (.not. period > 0) period = last%period   ! (a secant gone wild: the last period)
         end associate
         local%periodic%tip_amplitude = target
         local%periodic%period = period
         call find_autonomous_orbit(local, prepared, orbit, stat, errmsg, silent, start=predicted)
         if (stat /= 0) return
         branch%steps_taken = branch%steps_taken + orbit%map%steps_taken
         if (orbit%status == outcome_interrupted) then
            branch%status = outcome_interrupted
            exit
         end if
         if (.not. (orbit%converged .and. orbit%status == outcome_ok)) then
            ds = ds/2
            halvings = halvings + 1
            if (halvings > max_halvings) then
               branch%status = outcome_failed
               branch%failure = 'the backbone could not be continued beyond point '//integer_text(n)//' ('// &
                                trim(branch%axis%parameter)//' = '//real_text(branch%points(n)%parameter)// &
                                ' m): Gauss-Newton failed with steps down to 2^-'//integer_text(max_halvings)// &
                                ' of the first ('//trim(orbit%failure)//')'
               exit
            end if
            cycle
         end if
         halvings = 0
         call set_point(orbit, target, ds, point)
         branch%points = [branch%points, point]
         call report()
         if (at_end) exit
         if (orbit%iterations <= easy_iterations) ds = sign(min(step_growth*abs(ds), largest_step*abs(first_step)), ds)
      end do
      stat = 0
      errmsg = ''
   contains
      !> `target` shortened to the bound it passes (parameter_max with a step up,
      !! parameter_min with a step down), `at_end` when it lies on it.
      subroutine clip_to_bound(target, at_end)
         real(dp), intent(inout) :: target
         logical, intent(out) :: at_end
         at_end = .false.
         if (first_step > 0 .and. .not. is_unset(scene%periodic%parameter_max)) then
            at_end = target >= scene%periodic%parameter_max
            if (at_end) target = scene%periodic%parameter_max
         else if (first_step < 0 .and. .not. is_unset(scene%periodic%parameter_min)) then
            at_end = target <= scene%periodic%parameter_min
            if (at_end) target = scene%periodic%parameter_min
         end if
      end subroutine clip_to_bound

      subroutine report()
         associate (last => branch%points(size(branch%points)))
            if (meter%due()) call meter%report('backbone point '//integer_text(size(branch%points))//': '// &
                                               trim(branch%axis%parameter)//' = '//real_text(last%parameter)// &
                                               ' m, period '//real_text(last%period)//' s')
         end associate
      end subroutine report
   end subroutine continue_backbone

   !> `point`: the branch point of the converged autonomous `orbit` at the amplitude
   !! `amplitude`, reached by the step `step` (m).
   subroutine set_point(orbit, amplitude, step, point)
      type(periodic_orbit), intent(in) :: orbit
      real(dp), intent(in) :: amplitude, step
      type(branch_point), intent(out) :: point
      ! (allocated with their source: gfortran's -Wmaybe-uninitialized does not follow an
      ! assignment's reallocation of a dummy's component)
      allocate (point%x, source=orbit%x)
      allocate (point%multipliers, source=orbit%multipliers)
      point%parameter = amplitude
      point%amplitude = maxval(abs(orbit%image%tip(1, :)))
      point%minimum_gap = orbit%image%minimum_gap
      point%period = orbit%map%steps*orbit%dt
      point%step = step
      point%iterations = orbit%iterations
      point%stable_margin = trivial_pair_splitting(point%multipliers)
   end subroutine set_point

   !> How far the monodromy's errors moved the two multipliers at 1 of an autonomous orbit
   !! of a conservative scene (its own direction and the family's, a Jordan block: a matrix
   !! error delta splits it by about sqrt(delta), far more than the delta that moves a simple
   !! multiplier): the larger distance from 1 of the two multipliers nearest 1 (0 with fewer
   !! than two). The backbone's points count a multiplier as on the unit circle up to that.
   pure real(dp) function trivial_pair_splitting(multipliers) result(splitting)
      real(dp), intent(in) :: multipliers(:, :)   !! (2, n) real and imaginary parts
      real(dp) :: distance(size(multipliers, 2))
      integer :: nearest
      splitting = 0
      if (size(multipliers, 2) < 2) return
      distance = hypot(multipliers(1, :) - 1, multipliers(2, :))
      nearest = minloc(distance, dim=1)
      distance(nearest) = huge(1.0_dp)
      splitting = max(hypot(multipliers(1, nearest) - 1, multipliers(2, nearest)), minval(distance))
   end function trivial_pair_splitting
end module vibrobeam_backbone
