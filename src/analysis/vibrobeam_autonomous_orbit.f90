!> Autonomous periodic orbits: the free vibration of a conservative scene, its period an
!! unknown (&periodic autonomous = .true.; docs/method.md, "Autonomous periodic orbits").
!! The unknowns are x = (U, V), the state at the orbit's start, and the period T; the map
!! Phi_T is P = steps_per_period steps of dt = T/P (`vibrobeam_period_map`, the forced
!! orbit's map at a dt that moves with T). The equations: Phi_T(x) - x = 0, the phase
!! condition v_tip(x) = 0 (the orbit starts where the tip turns, as Peeters et al. 2009
!! start nonlinear normal modes) and the amplitude condition u_tip(x) = A (&periodic
!! tip_amplitude, or the start's own tip displacement), which picks one orbit of the
!! conservative scene's one-parameter family: 2 J + 2 equations in 2 J + 1 unknowns,
!! consistent, of full column rank, solved by Gauss-Newton (LAPACK dgels on the scaled
!! Jacobian), which converges quadratically on a consistent system. dPhi/dx is the
!! forced orbit's monodromy (linearised steps or differences), dPhi/dT a forward
!! difference. The problem (model, reduced basis) is the one built at the period's
!! guess: only the step changes with T.
module vibrobeam_autonomous_orbit
   use vibrobeam_kinds, only: dp, int64, pi
   use vibrobeam_status, only: outcome_ok, outcome_failed, outcome_interrupted
   use vibrobeam_text, only: real_text, integer_text
   use vibrobeam_scene, only: scene_type
   use vibrobeam_schema_visitor, only: is_unset
   use vibrobeam_problem, only: run_problem
   use vibrobeam_period_map, only: map_image, jacobian_linearised, jacobian_differences, jacobian_none, &
      difference_fraction
   use vibrobeam_periodic_analysis, only: periodic_orbit, publish_orbit, settle_start, conclude_orbit
   use vibrobeam_result_files, only: run_outcome
   use vibrobeam_progress, only: progress_meter
   use vibrobeam_lapack, only: dgels
   implicit none
   private
   public :: run_autonomous, find_autonomous_orbit

   !> Halvings of a Gauss-Newton step that does not reduce the residual, before it is taken whole.
   integer, parameter :: max_halvings = 4

contains

   !> Find the autonomous orbit of the prepared scene and publish it (`publish_orbit`, as
   !! `run_periodic`: stat /= 0 when the result cannot be written or a stepper made; a
   !! search that fails is `outcome%status` 'failed', its last iterate published).
   subroutine run_autonomous(scene, prepared, outcome, stat, errmsg)
      type(scene_type), intent(in) :: scene
      type(run_problem), intent(in) :: prepared
      type(run_outcome), intent(out) :: outcome
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      type(periodic_orbit) :: orbit
      type(progress_meter) :: meter
      call meter%init(scene%output%progress)
      call find_autonomous_orbit(scene, prepared, orbit, stat, errmsg, meter)
      if (stat /= 0) return
      call publish_orbit(scene, prepared, orbit, meter, outcome, stat, errmsg)
   end subroutine run_autonomous

   !> The autonomous orbit of the prepared scene (module documentation) in `orbit`:
   !! orbit%dt = T/P its step (T = P dt the period found), orbit%x its start, the Floquet
   !! multipliers those of dPhi_T/dx there. Its status says whether Gauss-Newton converged
   !! ('ok') or not ('failed', `failure` says why), or was interrupted. stat /= 0 (errmsg):
   !! a stepper could not be made, a step could not be linearised, or the multipliers
   !! could not be computed. `start` (optional, the stepper's (U, V)): Gauss-Newton's
   !! start instead of the scene's start and transient (the backbone's predictor,
   !! `vibrobeam_backbone`; the period's guess is then the scene's &periodic period).
   subroutine find_autonomous_orbit(scene, prepared, orbit, stat, errmsg, meter, start)
      type(scene_type), intent(in) :: scene
      type(run_problem), intent(in) :: prepared
      type(periodic_orbit), intent(out) :: orbit
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      type(progress_meter), intent(inout) :: meter   !! reports the iterations (a default one: silent)
      real(dp), intent(in), optional :: start(:)
      orbit%autonomous = .true.
      orbit%map%steps = int(scene%periodic%steps_per_period, int64)
      orbit%map%unknowns = prepared%system%model%unknowns
      ! the energy norm weighs U at the angular frequency of the guess
      orbit%map%omega = 2*pi/scene%periodic%period
      orbit%dt = scene%periodic%period/scene%periodic%steps_per_period
      call settle_start(scene, prepared, orbit%map%steps, orbit, stat, errmsg, start)
      if (stat /= 0) return
      if (orbit%status == outcome_ok) call solve(scene, prepared, meter, orbit, stat, errmsg)
      if (stat == 0) call conclude_orbit(orbit, stat, errmsg)
   end subroutine find_autonomous_orbit

   !> Gauss-Newton on (Phi_T(x) - x, v_tip(x), u_tip(x) - A) = 0 from orbit%x and the
   !! period's guess: each iteration evaluates Phi_T and dPhi_T/dx at (x, T), dPhi/dT by
   !! a forward difference, solves the scaled least-squares problem for the step (dgels)
   !! and takes it, halved (at most max_halvings times) while that does not reduce the
   !! residual. It stops when the relative residual is at most the tolerance, after
   !! max_iterations, or at a failure; Phi_T and dPhi_T/dx of the last iterate stay in
   !! orbit%image.
   subroutine solve(scene, prepared, meter, orbit, stat, errmsg)
      type(scene_type), intent(in) :: scene
      type(run_problem), intent(in) :: prepared
      type(progress_meter), intent(inout) :: meter
      type(periodic_orbit), intent(inout) :: orbit
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      type(map_image) :: shifted, trial
      real(dp), allocatable :: weights(:), jacobian(:, :), rhs(:), work(:), moved(:), derivative(:)
      real(dp) :: period, amplitude, residual, trial_residual, relative, phase_weight, amplitude_weight, period_weight, &
                  h, moved_period, query(1)
      integer :: n, m, monodromy, halving, info, j
      n = orbit%map%unknowns
      m = 2*n
      period = scene%periodic%period
      monodromy = merge(jacobian_linearised, jacobian_differences, orbit%monodromy == 'linearised')
      ! (allocated first: gfortran's -Wmaybe-uninitialized does not follow a function
      ! result's reallocation)
      allocate (weights(m))
      weights = orbit%map%weights(prepared)
      do
         call evaluate(orbit%x, period, monodromy, orbit%image)
         if (stat /= 0 .or. .not. usable(orbit%image)) return
         if (size(orbit%residuals) == 0) then
            ! the amplitude condition's A, and the rows' weights: the tip's row over the
            ! unknowns' weights, so that each condition is measured in the energy norm's units
            amplitude = orbit%image%tip(1, 0)
            if (.not. is_unset(scene%periodic%tip_amplitude)) amplitude = scene%periodic%tip_amplitude
            if (.not. abs(amplitude) > 0) then
               orbit%status = outcome_failed
               orbit%failure = 'the orbit''s tip amplitude is 0 (the start''s tip displacement, &periodic '// &
                               'tip_amplitude not given): that is the rest state, whose period is undetermined; give '// &
                               'tip_amplitude, or start from a displacement (&initial displacement = ''mode'')'
               return
            end if
            amplitude_weight = 1/norm2(orbit%image%tip_row/weights(1:n))
            phase_weight = 1/norm2(orbit%image%tip_row/weights(n + 1:m))
         end if
         call measure(orbit%x, orbit%image, residual, relative)
         orbit%residuals = [orbit%residuals, relative]
         orbit%dt = period/orbit%map%steps
         if (meter%due()) call meter%report('Gauss-Newton iteration '//integer_text(orbit%iterations)// &
                                            ': residual '//real_text(relative)//', period '//real_text(period)//' s')
         if (relative <= scene%periodic%tolerance) then
            orbit%converged = .true.
            return
         end if
         if (orbit%iterations >= scene%periodic%max_iterations) then
            orbit%failure = 'Gauss-Newton did not converge in '//integer_text(orbit%iterations)// &
                            ' iterations: relative residual '//real_text(relative)//' > tolerance '// &
                            real_text(scene%periodic%tolerance)//' (the smallest reached: '// &
                            real_text(minval(orbit%residuals))//'; docs/method.md, "Autonomous periodic orbits")'
            return
         end if
         ! dPhi/dT by a forward difference (the step actually taken after rounding)
         h = difference_fraction*period
         moved_period = period + h
         call evaluate(orbit%x, moved_period, jacobian_none, shifted)
         if (stat /= 0) return
         if (shifted%status /= outcome_ok) then
            orbit%status = shifted%status
            orbit%failure = 'dPhi/dT: '//trim(shifted%failure)
            return
         end if
         derivative = (shifted%state - orbit%image%state)/(moved_period - period)
         ! the scaled system: rows and columns of the unknowns by their weights, T by the
         ! state's size over the period (a relative change of T counts as one of x)
         period_weight = norm2(weights*orbit%x)/period
         if (.not. period_weight > 0) period_weight = 1/period
         allocate (jacobian(m + 2, m + 1), source=0.0_dp)
         jacobian(1:m, 1:m) = orbit%image%jacobian
         do j = 1, m
            jacobian(j, j) = jacobian(j, j) - 1
         end do
         jacobian(1:m, m + 1) = derivative
         jacobian(m + 1, n + 1:m) = orbit%image%tip_row*phase_weight
         jacobian(m + 2, 1:n) = orbit%image%tip_row*amplitude_weight
         do j = 1, m
            jacobian(j, :) = jacobian(j, :)*weights(j)
            jacobian(:, j) = jacobian(:, j)/weights(j)
         end do
         jacobian(:, m + 1) = jacobian(:, m + 1)/period_weight
         rhs = -[weights*(orbit%image%state - orbit%x), orbit%image%tip(2, 0)*phase_weight, &
                 (orbit%image%tip(1, 0) - amplitude)*amplitude_weight]
         call dgels('N', m + 2, m + 1, 1, jacobian, m + 2, rhs, m + 2, query, -1, info)
         allocate (work(max(1, int(query(1)))))
         call dgels('N', m + 2, m + 1, 1, jacobian, m + 2, rhs, m + 2, work, size(work), info)
         deallocate (jacobian, work)
         if (info /= 0) then
            orbit%status = outcome_failed
            orbit%failure = 'the Gauss-Newton system is rank deficient (LAPACK dgels, info = '//integer_text(info)// &
                            '): the phase and amplitude conditions do not fix the orbit (a start at rest, or a '// &
                            'multiplier at 1 the conservative family does not explain)'
            return
         end if
         rhs(1:m) = rhs(1:m)/weights
         rhs(m + 1) = rhs(m + 1)/period_weight
         trial_residual = huge(1.0_dp)
         do halving = 0, max_halvings
            moved = orbit%x + rhs(1:m)/2.0_dp**halving
            moved_period = period + rhs(m + 1)/2.0_dp**halving
            if (.not. moved_period > 0) cycle
            call evaluate(moved, moved_period, jacobian_none, trial)
            if (stat /= 0) return
            if (trial%status == outcome_interrupted) then
               orbit%status = outcome_interrupted
               return
            end if
            if (trial%status /= outcome_ok) cycle   ! (a step that failed: shorter)
            call measure(moved, trial, trial_residual, relative)
            if (trial_residual < residual) exit
         end do
         if (.not. (trial%status == outcome_ok .and. trial_residual < residual)) then
            ! no shorter step reduces the residual: the whole one (a period map whose
            ! pieces change within the step; the next iteration's Jacobian is taken there)
            moved = orbit%x + rhs(1:m)
            moved_period = period + rhs(m + 1)
            if (.not. moved_period > 0) then
               orbit%status = outcome_failed
               orbit%failure = 'Gauss-Newton''s step makes the period '//real_text(moved_period)//' s, not > 0: '// &
                               'give a better &periodic period'
               return
            end if
         end if
         orbit%x = moved
         period = moved_period
         orbit%iterations = orbit%iterations + 1
      end do
   contains
      !> Phi_T(x) (and dPhi_T/dx by `jacobian`) at the period `at`: the scene's stepper at
      !! dt = at/P on the problem built at the guess.
      subroutine evaluate(x, at, jacobian, image)
         real(dp), intent(in) :: x(:), at
         integer, intent(in) :: jacobian
         type(map_image), intent(out) :: image
         type(scene_type) :: local
         local = scene
         local%time%dt = at/orbit%map%steps
         call orbit%map%evaluate(local, prepared, x, jacobian, image, stat, errmsg)
      end subroutine evaluate

      !> The evaluation ran to its end; otherwise its status and reason become the orbit's.
      logical function usable(image)
         type(map_image), intent(in) :: image
         usable = image%status == outcome_ok
         if (usable) return
         orbit%status = image%status
         orbit%failure = image%failure
      end function usable

      !> The residual sqrt(||Phi(x) - x||^2 + (phase)^2 + (amplitude)^2), each condition
      !! weighted as in the scaled system, and it relative to max(||x||, ||Phi(x)||) (0 when
      !! both are 0).
      subroutine measure(x, image, absolute, relative)
         real(dp), intent(in) :: x(:)
         type(map_image), intent(in) :: image
         real(dp), intent(out) :: absolute, relative
         real(dp) :: scale
         absolute = hypot(orbit%map%norm(prepared, image%state - x), &
                          hypot(image%tip(2, 0)*phase_weight, (image%tip(1, 0) - amplitude)*amplitude_weight))
         scale = max(orbit%map%norm(prepared, x), orbit%map%norm(prepared, image%state))
         relative = 0
         if (scale > 0) relative = absolute/scale
      end subroutine measure
   end subroutine solve
end module vibrobeam_autonomous_orbit
