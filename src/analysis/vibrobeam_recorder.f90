!> Histories of a dynamics run, streamed into the result file while the run goes on
!! (docs/output.md, "HDF5 layout" and "Streaming"; docs/method.md, "Impacts and contact
!! statistics").
!!
!! The time loop calls, for step n (global step number, t = n dt):
!! - `after_step` after every step: impacts (streamed to /impacts), contact episodes
!!   (`vibrobeam_episodes`, an observer), the time each contact point spends in contact,
!!   the tip impulse since the last output, the largest penetration, contact-solver counts;
!! - `sample` when `output_due(n)`: one row of every history (/time, /tip, /energy,
!!   /contact/penetration, /points) at t = 0, every `every` steps and the last step;
!! - `sample_field` when `field_due(n)`: one snapshot (/field/time, /field/displacement)
!!   at t = 0, every `field_every` steps and the last step;
!! - `write_buffers` at every flush, `finish` at the end.
!! Memory is bounded: rows wait in fixed-size buffers (`vibrobeam_hdf5_series`), the
!! spectra are streaming Welch estimates (`vibrobeam_run_spectra`), per-point state is one
!! value per contact or observation point.
!!
!! Everything a continued run needs to go on as if uninterrupted goes into a checkpoint
!! (`save_state`/`restore_state`). Accumulators that observe every step (episodes, the
!! statistics over the window of &output measure_from, `vibrobeam_statistics`) extend
!! `step_observer` and are called from here, so the time loop does not change when one
!! is added.
!!
!! Without a file (`init` with write_rows = .false., a sweep's points) the recorder only
!! decides impacts and episodes and feeds the statistics; `sample` and the dataset
!! procedures are then not called.
module vibrobeam_recorder
   use vibrobeam_kinds, only: dp, int64
   use vibrobeam_text, only: real_text
   use vibrobeam_scene, only: scene_type, is_unset, forcing_of
   use vibrobeam_model, only: beam_model, nodal_displacement, point_row, node_row
   use vibrobeam_modes, only: reference_frequencies
   use vibrobeam_reduction, only: reduced_basis
   use vibrobeam_contact_set, only: contact_value
   use vibrobeam_time_stepper, only: time_stepper
   use vibrobeam_problem, only: run_problem
   use vibrobeam_hdf5, only: h5_writer
   use vibrobeam_support_wear, only: support_wear
   use vibrobeam_histories, only: run_histories, history_paths, history_count, h_time, h_tip_u, h_tip_v, &
      h_tip_reaction, h_tip_impulse, h_kinetic, h_elastic, h_total, h_work, h_dissipated, h_impacts, h_damping, &
      h_numerical, h_balance, h_penetration
   use vibrobeam_state_record, only: state_record
   use vibrobeam_step_observer, only: step_events
   use vibrobeam_episodes, only: episode_tracker
   use vibrobeam_run_spectra, only: run_spectra
   use vibrobeam_forces_psd, only: forces_psd
   use vibrobeam_statistics, only: run_statistics, statistics_result, window_first_step
   use vibrobeam_statistics_output, only: statistics_datasets
   implicit none
   private
   public :: dynamics_recorder, default_episode_gap, history_paths, statistics_options

   type :: dynamics_recorder
      integer(int64) :: every = 1, field_every = 1   !! output intervals (steps)
      integer(int64) :: last_step = 0                !! the run's last step
      integer(int64) :: last_output_step = -1        !! step of the last history row
      integer(int64) :: last_field_step = -1         !! step of the last field snapshot
      real(dp) :: last_output_time = 0               !! its time (s)
      integer :: tip_contact = 0                     !! contact point at the tip, 0 if none
      real(dp) :: tip_impulse = 0                    !! tip impulse since the last output (N s)
      !> contact point had a rigid impulse last step (the springs' force does not count:
      !! a rigid obstacle behind a spring still logs its impacts)
      logical, allocatable :: in_contact(:)
      logical, allocatable :: touched(:)             !! work space of `after_step`: in contact this step
      real(dp), allocatable :: contact_time(:)       !! time spent in contact per point (s)
      real(dp) :: max_penetration = 0                !! over every step (m)
      real(dp) :: max_penetration_time = 0
      integer(int64) :: impacts = 0                  !! impacts since t = 0
      ! contact-solver work of this process (not carried over by a restart)
      integer(int64) :: iterations_total = 0, linear_solves_total = 0, fallback_steps = 0
      integer :: iterations_max = 0, linear_solves_max = 0
      ! observation points (&output points): rows of the shape functions
      real(dp), allocatable :: point_x(:)
      integer, allocatable :: point_dofs(:, :)       !! (4, points)
      real(dp), allocatable :: point_weights(:, :)   !! (4, points)
      !> rows of the tip (1) and of the observation points (2..): (4, 1 + points)
      integer, allocatable :: observed_dofs(:, :)
      real(dp), allocatable :: observed_weights(:, :)
      real(dp) :: length = 0
      real(dp) :: measure_from = 0                   !! &output measure_from (s)
      character(len=16) :: forcing = 'none'          !! the load whose phase times the Poincare samples
      logical :: write_rows = .true.                 !! a result file receives the histories
      ! a reduced model (&mesh reduction): the stepper's unknowns are q, U = T q
      type(reduced_basis), allocatable :: reduction   !! T, for field snapshots
      real(dp), allocatable :: observed_rows(:, :)   !! (r, 1 + points) u_h at the tip and points = row . q
      integer :: planes = 1   !! bending planes of the stepper; 2: events%observed_z holds z
      type(support_wear) :: wear                     !! impacts, forces, sliding and wear at those points
      type(run_spectra) :: spectra                   !! /spectrum: the tip's and the observation points'
      type(forces_psd) :: forces_spectra             !! /forces: the random loads' densities (none without)
      type(episode_tracker) :: episodes
      type(run_statistics) :: statistics
      type(statistics_datasets) :: statistics_files
      type(step_events) :: events
      type(run_histories) :: files                   !! the datasets of the result file
      logical :: compliant = .false.                 !! the scene has compliant stops (docs/output.md)
      real(dp), allocatable :: peak_force(:)         !! largest |force| per contact point over every step (N)
   contains
      procedure :: init => recorder_init
      procedure :: observed_row
      procedure :: create_datasets
      procedure :: after_step
      procedure :: output_due
      procedure :: field_due
      procedure :: sample
      procedure :: sample_field
      procedure :: record_step
      procedure :: write_buffers
      procedure :: rows
      procedure :: finish
      procedure :: save_state
      procedure :: restore_state
      procedure :: observe
      procedure :: start_statistics
      procedure :: restart_statistics
      procedure :: restart_wear
      procedure :: window_statistics
   end type dynamics_recorder

contains

   !> What the statistics of `scene` hold beyond the planar ones (`vibrobeam_statistics_layout`),
   !! `option` 'wear_volume' (some obstacle of a beam of two planes gives a wear_coefficient)
   !! or 'friction' (some gives a friction coefficient, 0 too): one rule for a run's layout
   !! and a sweep's, whose every point must hold the same.
   pure logical function statistics_options(scene, option)
      type(scene_type), intent(in) :: scene
      character(len=*), intent(in) :: option
      statistics_options = .false.
      if (scene%beam%plane_count() /= 2) return
      select case (option)
      case ('wear_volume')
         statistics_options = any(.not. is_unset(scene%obstacles%wear_coefficient))
      case ('friction')
         statistics_options = any(.not. is_unset(scene%obstacles%friction))
      end select
   end function statistics_options

   !> The default of &output episode_gap: 0.05 of the period 2 pi/omega of the first
   !! flexible mode of the beam on the model's supports (`reference_frequencies`: the
   !! continuum's closed form where there is one) (s); 0 when it has none.
   function default_episode_gap(model) result(gap)
      type(beam_model), intent(in) :: model
      real(dp) :: gap, omega(3)
      logical :: closed_form
      integer :: stat, first
      character(len=256) :: errmsg
      call reference_frequencies(model%structure, model%length, model%rho_s, model%ei, omega, closed_form, stat, errmsg)
      first = findloc(omega > 0, .true., dim=1)
      gap = 0
      if (stat == 0 .and. first > 0) gap = 0.05_dp*2*acos(-1.0_dp)/omega(first)
   end function default_episode_gap

   !> Set up for a run that ends at step `last_step`. `v0` is the initial velocity of the
   !! scene: a contact point that starts on its obstacle (within the activation tolerance
   !! 1e-12 L) without moving into it is in persistent contact from t = 0, so its first
   !! impulse is not an impact.
   !! When the problem is reduced the stepper runs a reduced model (its u, v are q, dq/dt,
   !! and its contact rows act on q): tip and observation points are read through rows of T
   !! (r products per value) and U = T q is formed only for a field snapshot.
   subroutine recorder_init(self, scene, stepper, problem, last_step, write_rows)
      class(dynamics_recorder), intent(inout) :: self
      type(scene_type), intent(in) :: scene
      class(time_stepper), intent(in) :: stepper
      type(run_problem), intent(in) :: problem       !! its model (the mesh), start and reduced basis
      integer(int64), intent(in) :: last_step
      logical, intent(in), optional :: write_rows   !! default .true.; .false.: no result file
      real(dp) :: value, speed, tolerance, gap, omega, phase
      integer :: c, p, contacts
      character(len=:), allocatable :: forcing
      contacts = stepper%contacts%count
      associate (model => problem%model)
      if (present(write_rows)) self%write_rows = write_rows
      self%every = scene%output%every
      self%field_every = scene%output%every
      if (scene%output%field_every > 0) self%field_every = scene%output%field_every
      self%last_step = last_step
      self%length = model%length
      self%planes = stepper%planes
      allocate (self%in_contact(contacts), self%touched(contacts), source=.false.)
      allocate (self%contact_time(contacts), source=0.0_dp)
      self%compliant = stepper%contacts%springs%count > 0
      allocate (self%peak_force(contacts), source=0.0_dp)
      allocate (self%events%impact(contacts), source=.false.)
      tolerance = 1e-12_dp*model%length
      self%tip_contact = 0
      do c = 1, contacts
         if (stepper%contacts%node(c) == model%elements) self%tip_contact = c
         value = contact_value(stepper%contacts, c, stepper%u)
         speed = contact_value(stepper%contacts, c, problem%start%v)
         if ((value <= stepper%contacts%lower(c) + tolerance .and. speed >= 0) .or. &
             (value >= stepper%contacts%upper(c) - tolerance .and. speed <= 0)) self%in_contact(c) = .true.
      end do
      if (stepper%holes%circles%count > 0) &
         call self%wear%init(stepper, problem%start%v, tolerance, &
                             window_first_step(scene%output%measure_from, scene%time%dt), &
                             wear_coefficients(stepper%holes%circles%obstacle))
      self%max_penetration = penetration(stepper)
      self%max_penetration_time = stepper%t
      self%point_x = scene%output%points
      allocate (self%point_dofs(4, size(self%point_x)), self%point_weights(4, size(self%point_x)))
      do p = 1, size(self%point_x)
         call point_row(model, self%point_x(p), self%point_dofs(:, p), self%point_weights(:, p))
      end do
      ! the tip is node N: the same row as /field/displacement's last node
      allocate (self%observed_dofs(4, 1 + size(self%point_x)), self%observed_weights(4, 1 + size(self%point_x)))
      call node_row(model, model%elements, self%observed_dofs(:, 1), self%observed_weights(:, 1))
      self%observed_dofs(:, 2:) = self%point_dofs
      self%observed_weights(:, 2:) = self%point_weights
      allocate (self%events%observed(1 + size(self%point_x), 2))
      allocate (self%events%observed_z(1 + size(self%point_x), 2), source=0.0_dp)
      call self%spectra%init(self%every*scene%time%dt, last_step/self%every + 1, self%point_x, self%planes)
      if (self%write_rows) call self%forces_spectra%init(scene%forces, problem%loads%forces, last_step)
      gap = scene%output%episode_gap
      if (is_unset(gap)) gap = default_episode_gap(model)
      call self%episodes%init(stepper%contacts%x, gap, self%write_rows)
      allocate (self%events%closed_point(contacts), self%events%closed_impulse(contacts), self%events%opened(contacts))
      forcing = forcing_of(scene, omega, phase)
      self%forcing = forcing
      self%measure_from = scene%output%measure_from
      call self%statistics%init(window_first_step(scene%output%measure_from, scene%time%dt), last_step, scene%time%dt, &
                                1 + size(self%point_x), stepper%contacts%lower_obstacle, &
                                stepper%contacts%upper_obstacle, size(scene%obstacles), omega, phase, &
                                scene%output%lyapunov, stepper, stepper%holes%circles%count, &
                                statistics_options(scene, 'wear_volume'), statistics_options(scene, 'friction'), &
                                scene%beam%plane_count())
      if (problem%reduced) then
         self%reduction = problem%reduction
         allocate (self%observed_rows(problem%reduction%boundary + problem%reduction%modes, size(self%observed_dofs, 2)))
         do p = 1, size(self%observed_dofs, 2)
            self%observed_rows(:, p) = reduced_row(self%observed_dofs(:, p), self%observed_weights(:, p))
         end do
      end if
      end associate
   contains
      !> Archard's coefficient of each point's obstacle (-1: not given).
      function wear_coefficients(obstacle) result(k)
         integer, intent(in) :: obstacle(:)
         real(dp) :: k(size(obstacle))
         integer :: i
         do i = 1, size(obstacle)
            k(i) = -1
            if (.not. is_unset(scene%obstacles(obstacle(i))%wear_coefficient)) &
               k(i) = scene%obstacles(obstacle(i))%wear_coefficient
         end do
      end function wear_coefficients

      !> The row sum_a weights(a) T(dofs(a), :) of a value of U.
      function reduced_row(dofs, weights) result(row)
         integer, intent(in) :: dofs(4)
         real(dp), intent(in) :: weights(4)
         real(dp) :: row(size(self%reduction%transform, 2))
         integer :: a
         row = 0
         do a = 1, 4
            if (dofs(a) /= 0) row = row + weights(a)*self%reduction%transform(dofs(a), :)
         end do
      end function reduced_row
   end subroutine recorder_init

   !> The recorder's work after step n: impacts, episodes, statistics (`after_step`) and,
   !! when it writes a result file, the samples due; the HDF5 part in the critical
   !! section `vibrobeam_hdf5` (HDF5 is not thread-safe: a sweep's keep_runs points write
   !! from several threads), the rest outside it.
   subroutine record_step(self, stepper, model, step, stat, errmsg)
      class(dynamics_recorder), intent(inout) :: self
      class(time_stepper), intent(in) :: stepper
      type(beam_model), intent(in) :: model
      integer(int64), intent(in) :: step
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      if (.not. self%write_rows) then
         call self%after_step(stepper, stat, errmsg)
         return
      end if
      if (allocated(self%forces_spectra%loads)) then
         call self%forces_spectra%add(step, stat, errmsg)
         if (stat /= 0) return
      end if
      !$omp critical (vibrobeam_hdf5)
      call self%after_step(stepper, stat, errmsg)
      if (stat == 0 .and. self%output_due(step)) call self%sample(stepper, stat, errmsg)
      if (stat == 0 .and. self%field_due(step)) call self%sample_field(stepper, model, stat, errmsg)
      !$omp end critical (vibrobeam_hdf5)
   end subroutine record_step

   !> u and v at the tip and at the observation points into events%observed (the same
   !! combinations of unknowns as /tip and /points).
   subroutine observe(self, stepper)
      class(dynamics_recorder), intent(inout) :: self
      class(time_stepper), intent(in) :: stepper
      integer :: p
      if (allocated(self%observed_rows)) then   ! a reduced model: rows of T times q
         do p = 1, size(self%observed_rows, 2)
            self%events%observed(p, 1) = dot_product(self%observed_rows(:, p), stepper%u)
            self%events%observed(p, 2) = dot_product(self%observed_rows(:, p), stepper%v)
         end do
         return
      end if
      do p = 1, size(self%observed_dofs, 2)
         self%events%observed(p, 1) = combination(self%observed_dofs(:, p), self%observed_weights(:, p), stepper%u)
         self%events%observed(p, 2) = combination(self%observed_dofs(:, p), self%observed_weights(:, p), stepper%v)
      end do
      if (self%planes == 2) then   ! the z plane: the same rows on the second half of the unknowns
         associate (j => size(stepper%u)/2)
            do p = 1, size(self%observed_dofs, 2)
               self%events%observed_z(p, 1) = combination(self%observed_dofs(:, p), self%observed_weights(:, p), &
                                                   stepper%u(j + 1:))
               self%events%observed_z(p, 2) = combination(self%observed_dofs(:, p), self%observed_weights(:, p), &
                                                   stepper%v(j + 1:))
            end do
         end associate
      end if
   end subroutine observe

   !> The row of observed point p (1: the tip, then the &output points) on the stepper's
   !! `unknowns` unknowns (of one plane): u_p = row . u, v_p = row . v, as `observe` takes them.
   function observed_row(self, p, unknowns) result(row)
      class(dynamics_recorder), intent(in) :: self
      integer, intent(in) :: p, unknowns
      real(dp) :: row(unknowns)
      integer :: a
      if (allocated(self%observed_rows)) then
         row = self%observed_rows(:, p)
         return
      end if
      row = 0
      do a = 1, 4
         if (self%observed_dofs(a, p) /= 0) row(self%observed_dofs(a, p)) = row(self%observed_dofs(a, p)) + &
                                                                             self%observed_weights(a, p)
      end do
   end function observed_row

   !> sum_a weights(a) unknowns(dofs(a)) over the dofs /= 0, in order.
   pure real(dp) function combination(dofs, weights, unknowns)
      integer, intent(in) :: dofs(4)
      real(dp), intent(in) :: weights(4), unknowns(:)
      integer :: a
      combination = 0
      do a = 1, 4
         if (dofs(a) /= 0) combination = combination + weights(a)*unknowns(dofs(a))
      end do
   end function combination

   !> Once the starting state is known (after `restore_state` for a continued run): the
   !! window starts now when it starts at this step. A continued run whose checkpoint lies
   !! past the window's start but holds no statistics of that window (another
   !! measure_from, other points) starts the window at the checkpoint; `warning` says so.
   subroutine start_statistics(self, stepper, warning)
      class(dynamics_recorder), intent(inout) :: self
      class(time_stepper), intent(in) :: stepper
      character(len=:), allocatable, intent(out) :: warning
      warning = ''
      if (.not. self%statistics%active .or. self%statistics%started) return
      if (stepper%steps > self%statistics%first_step) then
         warning = 'the checkpoint holds no statistics of the window from &output measure_from = '// &
                   real_text(self%measure_from)//' s: the statistics window starts at the checkpoint, t = '// &
                   real_text(stepper%t)//' s'
         call self%statistics%begin_window(stepper%steps)
      end if
      call self%observe(stepper)
      call self%statistics%observe_start(stepper, self%events%observed)
   end subroutine start_statistics

   !> A new statistics window from step `first_step` on (a sweep measures window after
   !! window): it starts now when the stepper is at that step.
   subroutine restart_statistics(self, stepper, first_step)
      class(dynamics_recorder), intent(inout) :: self
      class(time_stepper), intent(in) :: stepper
      integer(int64), intent(in) :: first_step
      call self%statistics%begin_window(first_step)
      call self%observe(stepper)
      call self%statistics%observe_start(stepper, self%events%observed)
   end subroutine restart_statistics

   !> The wear's window (`vibrobeam_support_wear`: a sweep measures window after window)
   !! from the state of step `first_step`.
   subroutine restart_wear(self, first_step)
      class(dynamics_recorder), intent(inout) :: self
      integer(int64), intent(in) :: first_step
      if (self%wear%active) call self%wear%begin_window(first_step)
   end subroutine restart_wear

   !> The statistics of the window so far (docs/statistics.md).
   function window_statistics(self, stepper) result(outcome)
      class(dynamics_recorder), intent(in) :: self
      class(time_stepper), intent(in) :: stepper
      type(statistics_result) :: outcome
      outcome = self%statistics%result(stepper, self%episodes%open, self%episodes%impulse)
      if (outcome%present .and. self%wear%active) call self%wear%into_statistics(outcome)
   end function window_statistics

   !> Create every dataset of the run (before the file enters SWMR mode) and write what is
   !! known from the start: /contact/x, /contact/lower, /contact/upper, /points/x.
   subroutine create_datasets(self, writer, stepper, model, stat, errmsg)
      class(dynamics_recorder), intent(inout) :: self
      type(h5_writer), intent(inout) :: writer
      class(time_stepper), intent(in) :: stepper
      type(beam_model), intent(in) :: model
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      call self%files%create(writer, self%point_x, stepper%contacts, model%elements + 1, self%compliant, self%planes, &
                             stepper%holes%circles%frictional(), stat, errmsg)
      if (stat == 0) call self%spectra%create(writer, stat, errmsg)
      if (stat == 0 .and. allocated(self%forces_spectra%loads)) call self%forces_spectra%create(writer, stat, errmsg)
      if (stat == 0) call self%episodes%create_datasets(writer, stat, errmsg)
      if (stat == 0 .and. self%compliant) call self%files%create_compliant(writer, stepper%contacts, stat, errmsg)
      if (stat == 0) call self%wear%create_datasets(writer, stepper%holes%circles, stat, errmsg)
      if (stat == 0 .and. self%statistics%active) &
         call self%statistics_files%create(writer, self%statistics%layout, [self%length, self%point_x], &
                                           stepper%contacts%x, stepper%contacts%lower_obstacle, &
                                           stepper%contacts%upper_obstacle, stepper%holes%circles%x, &
                                           stepper%holes%circles%obstacle, self%measure_from, trim(self%forcing), &
                                           self%statistics%poincare%omega, self%statistics%poincare%phase, stat, errmsg)
   end subroutine create_datasets

   !> Largest penetration of the current positions into an obstacle (m, >= 0).
   pure function penetration(stepper) result(depth)
      class(time_stepper), intent(in) :: stepper
      real(dp) :: depth, u
      integer :: c
      depth = 0
      do c = 1, stepper%contacts%count
         u = contact_value(stepper%contacts, c, stepper%u)
         depth = max(depth, stepper%contacts%lower(c) - u, u - stepper%contacts%upper(c))
      end do
      do c = 1, stepper%holes%circles%count   ! beyond a circle's (or a flat point's) wall
         depth = max(depth, stepper%holes%circles%penetration(c, stepper%u))
      end do
   end function penetration

   !> Bookkeeping after every step (module documentation). An impact is a rigid impulse at
   !! a contact point that received none in the previous step (nor rested on its obstacle
   !! at t = 0) and approached its obstacle (docs/method.md), whatever force compliant stops
   !! on the same point exert: a spring in front of a rigid wall does not hide the wall's
   !! impacts. The springs' force counts for the time in contact only.
   subroutine after_step(self, stepper, stat, errmsg)
      class(dynamics_recorder), intent(inout) :: self
      class(time_stepper), intent(in) :: stepper
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      real(dp) :: depth
      integer :: k, c
      stat = 0
      errmsg = ''
      associate (now => self%touched)
      now = .false.
      do k = 1, stepper%report%active_count
         c = stepper%report%active(k)
         self%events%impact(k) = .false.
         if (abs(stepper%report%impulse(k)) <= 0) cycle
         now(c) = .true.
         if (.not. self%in_contact(c) .and. stepper%report%approaching(k)) then
            self%events%impact(k) = .true.
            self%impacts = self%impacts + 1
            if (self%write_rows) call self%files%append_impact([stepper%report%impulse_time, stepper%contacts%x(c), &
                                                                stepper%report%impulse(k), &
                                                                stepper%report%velocity_before(k), &
                                                                stepper%report%velocity_after(k)], stat, errmsg)
            if (stat /= 0) return
         end if
         if (c == self%tip_contact) self%tip_impulse = self%tip_impulse + stepper%report%impulse(k)
      end do
      ! the next step's impact test sees the rigid impulses only
      self%in_contact = now
      call circle_impacts(stat, errmsg)
      if (stat /= 0) return
      if (self%compliant) then
         ! stepper%report%contact_force holds the true force at every contact point after every
         ! step; the run statistics take their force statistics from it (observe_step).
         ! a compliant point is in contact while its stops push (docs/output.md)
         where (abs(stepper%report%contact_force) > 0) now = .true.
         self%peak_force = max(self%peak_force, abs(stepper%report%contact_force))
      end if
      where (now) self%contact_time = self%contact_time + stepper%dt
      end associate
      depth = penetration(stepper)
      if (depth > self%max_penetration) then
         self%max_penetration = depth
         self%max_penetration_time = stepper%t
      end if
      self%iterations_total = self%iterations_total + stepper%report%iterations
      self%iterations_max = max(self%iterations_max, stepper%report%iterations)
      self%linear_solves_total = self%linear_solves_total + stepper%report%linear_solves
      self%linear_solves_max = max(self%linear_solves_max, stepper%report%linear_solves)
      if (stepper%report%used_fallback) self%fallback_steps = self%fallback_steps + 1
      call self%episodes%observe_step(stepper, self%events, stat, errmsg)
      if (stat /= 0 .or. .not. self%statistics%active) return
      ! the observed values, for the statistics
      call self%observe(stepper)
      call self%statistics%observe_step(stepper, self%events, stat, errmsg)
      if (stat /= 0) then
         errmsg = 'statistics: '//trim(errmsg)
         return
      end if
      if (self%write_rows .and. self%statistics%poincare_found > 0) &
         call self%statistics_files%append_poincare(self%statistics%sample_times(1:self%statistics%poincare_found), &
                                                    self%statistics%sample_values(:, 1:self%statistics%poincare_found), &
                                                    stat, errmsg)
   contains
      !> The impacts at the points of a beam of two planes' obstacles (`support_wear`
      !! decides them, as at the levels of a planar beam): their rows of /impacts, with the
      !! normal velocities (positive inwards) before and after.
      subroutine circle_impacts(stat, errmsg)
         integer, intent(out) :: stat
         character(len=*), intent(out) :: errmsg
         integer :: new(stepper%report%circle_count), count, i
         stat = 0
         errmsg = ''
         if (.not. self%wear%active) return
         call self%wear%observe_step(stepper, new, count)
         self%impacts = self%impacts + count
         if (.not. self%write_rows) return
         associate (r => stepper%report)
            do i = 1, count
               call self%files%append_impact([r%impulse_time, stepper%holes%circles%x(r%circle_active(new(i))), &
                                              r%circle_impulse(new(i)), r%circle_before(new(i)), &
                                              r%circle_after(new(i))], stat, errmsg)
               if (stat /= 0) return
            end do
         end associate
      end subroutine circle_impacts
   end subroutine after_step

   !> True when step n is an output time of the histories.
   pure logical function output_due(self, n)
      class(dynamics_recorder), intent(in) :: self
      integer(int64), intent(in) :: n
      output_due = mod(n, self%every) == 0 .or. n == self%last_step
   end function output_due

   !> True when step n is an output time of the field.
   pure logical function field_due(self, n)
      class(dynamics_recorder), intent(in) :: self
      integer(int64), intent(in) :: n
      field_due = mod(n, self%field_every) == 0 .or. n == self%last_step
   end function field_due

   !> One row of every history at the stepper's present time (a no-op when this step was
   !! sampled already).
   subroutine sample(self, stepper, stat, errmsg)
      class(dynamics_recorder), intent(inout) :: self
      class(time_stepper), intent(in) :: stepper
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      real(dp) :: row(history_count), interval, potential
      stat = 0
      errmsg = ''
      if (stepper%steps == self%last_output_step) return
      interval = stepper%t - self%last_output_time
      call self%observe(stepper)
      row(h_time) = stepper%t
      row(h_tip_u) = self%events%observed(1, 1)
      row(h_tip_v) = self%events%observed(1, 2)
      row(h_tip_impulse) = self%tip_impulse
      row(h_tip_reaction) = 0
      if (interval > 0) row(h_tip_reaction) = self%tip_impulse/interval
      row(h_kinetic) = stepper%kinetic_energy()
      row(h_elastic) = stepper%elastic_energy()
      row(h_total) = row(h_kinetic) + row(h_elastic)
      row(h_work) = stepper%energy%work
      row(h_impacts) = stepper%energy%dissipated_impacts
      row(h_damping) = stepper%energy%dissipated_damping
      row(h_numerical) = stepper%energy%dissipated_numerical
      row(h_dissipated) = row(h_impacts) + row(h_damping) + row(h_numerical) + stepper%energy%dissipated_friction
      potential = 0
      if (self%compliant .or. stepper%holes%circles%compliant) then
         ! the stops' stored energy is part of the total, their damping a dissipation
         potential = stepper%contact_potential()
         row(h_total) = row(h_total) + potential
         row(h_dissipated) = row(h_dissipated) + stepper%energy%dissipated_contact_damping
      end if
      row(h_balance) = row(h_total) - row(h_work) + row(h_dissipated)
      row(h_penetration) = penetration(stepper)
      associate (observed => self%events%observed, observed_z => self%events%observed_z)
         call self%files%append_sample(row, observed_z(1, :), stepper%energy%dissipated_friction, observed(2:, 1), &
                                       observed(2:, 2), observed_z(2:, 1), observed_z(2:, 2), potential, &
                                       stepper%energy%dissipated_contact_damping, stepper%report%contact_force, stat, errmsg)
      end associate
      if (stat /= 0) return
      ! the spectrum takes the uniformly spaced rows only (not a last row off the grid)
      if (mod(stepper%steps, self%every) == 0) call self%spectra%add(row(h_tip_u), self%events%observed(2:, 1), stat, &
                                                                      errmsg, self%events%observed_z(:, 1))
      if (stat /= 0) return
      self%tip_impulse = 0
      self%last_output_step = stepper%steps
      self%last_output_time = stepper%t
   end subroutine sample

   !> One field snapshot at the stepper's present time (a no-op when taken already).
   subroutine sample_field(self, stepper, model, stat, errmsg)
      class(dynamics_recorder), intent(inout) :: self
      class(time_stepper), intent(in) :: stepper
      type(beam_model), intent(in) :: model
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer :: plane
      stat = 0
      errmsg = ''
      if (stepper%steps == self%last_field_step) return
      if (allocated(self%reduction)) then
         call self%files%append_field(stepper%t, nodal_displacement(model, self%reduction%expand(stepper%u)), stat, &
                                      errmsg)
      else   ! each plane's J unknowns (a beam of two planes has those in z after those in y)
         call self%files%append_field(stepper%t, [(nodal_displacement(model, stepper%u((plane - 1)*model%unknowns + 1: &
                                      plane*model%unknowns)), plane = 1, self%planes)], stat, errmsg)
      end if
      self%last_field_step = stepper%steps
   end subroutine sample_field

   !> Write every buffered row to the file (at a flush).
   subroutine write_buffers(self, stat, errmsg)
      class(dynamics_recorder), intent(inout) :: self
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      call self%files%write(stat, errmsg)
      if (stat == 0) call self%episodes%write_buffers(stat, errmsg)
      if (stat == 0) call self%files%write_compliant(stat, errmsg)
      if (stat == 0) call self%statistics_files%write_buffers(stat, errmsg)
   end subroutine write_buffers

   !> Rows so far: [outputs, field snapshots, impacts, episodes].
   function rows(self) result(counts)
      class(dynamics_recorder), intent(in) :: self
      integer(int64) :: counts(4)
      counts = [self%files%rows(), self%episodes%rows()]
   end function rows

   !> End of the run: the spectrum, the contact fractions and largest penetration, the
   !! open episodes, and every buffered row; the datasets are closed.
   subroutine finish(self, writer, stepper, stat, errmsg)
      class(dynamics_recorder), intent(inout) :: self
      type(h5_writer), intent(inout) :: writer
      class(time_stepper), intent(in) :: stepper
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      call self%statistics_files%finish(writer, self%window_statistics(stepper), stat, errmsg)
      if (stat == 0) call self%episodes%finish(writer, stat, errmsg)
      if (stat == 0) call self%write_buffers(stat, errmsg)
      if (stat /= 0) return
      call self%files%finish(writer, self%contact_time/max(stepper%t, tiny(1.0_dp)), self%max_penetration, &
                             self%max_penetration_time, self%impacts, self%peak_force, stat, errmsg)
      if (stat == 0) call self%wear%write(stat, errmsg)
      if (stat == 0) call self%spectra%finish(writer, stat, errmsg)
      call self%spectra%close()
      if (allocated(self%forces_spectra%loads)) then
         if (stat == 0) call self%forces_spectra%finish(writer, stat, errmsg)
         call self%forces_spectra%close()
      end if
   end subroutine finish

   !> Everything a continued run needs (module documentation).
   subroutine save_state(self, record)
      class(dynamics_recorder), intent(in) :: self
      type(state_record), intent(inout) :: record
      call record%put_int64s('recorder.steps', [self%last_output_step, self%last_field_step, self%impacts])
      call record%put_reals('recorder.values', [self%last_output_time, self%tip_impulse, self%max_penetration, &
                                                self%max_penetration_time])
      call record%put_logicals('recorder.in_contact', self%in_contact)
      call record%put_reals('recorder.contact_time', self%contact_time)
      if (self%compliant) call record%put_reals('recorder.peak_force', self%peak_force)
      call self%spectra%save_state(record)
      if (allocated(self%forces_spectra%loads)) call self%forces_spectra%save_state(record)
      call self%episodes%save_state(record)
      call self%statistics%save_state(record)
      call self%wear%save_state(record)
   end subroutine save_state

   !> Take back what `save_state` put into `record`.
   subroutine restore_state(self, record, stat, errmsg)
      class(dynamics_recorder), intent(inout) :: self
      type(state_record), intent(in) :: record
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer(int64) :: counts(3)
      real(dp) :: values(4)
      call record%get_int64s('recorder.steps', counts, stat, errmsg)
      if (stat == 0) call record%get_reals('recorder.values', values, stat, errmsg)
      if (stat == 0) call record%get_logicals('recorder.in_contact', self%in_contact, stat, errmsg)
      if (stat == 0) call record%get_reals('recorder.contact_time', self%contact_time, stat, errmsg)
      if (stat == 0 .and. self%compliant) call record%get_reals('recorder.peak_force', self%peak_force, stat, errmsg)
      if (stat == 0) call self%spectra%restore_state(record, stat, errmsg)
      if (stat == 0 .and. allocated(self%forces_spectra%loads)) call self%forces_spectra%restore_state(record, stat, errmsg)
      if (stat == 0) call self%episodes%restore_state(record, stat, errmsg)
      if (stat == 0) call self%statistics%restore_state(record, stat, errmsg)
      if (stat == 0) call self%wear%restore_state(record, stat, errmsg)
      if (stat /= 0) return
      self%last_output_step = counts(1)
      self%last_field_step = counts(2)
      self%impacts = counts(3)
      self%last_output_time = values(1)
      self%tip_impulse = values(2)
      self%max_penetration = values(3)
      self%max_penetration_time = values(4)
   end subroutine restore_state
end module vibrobeam_recorder
