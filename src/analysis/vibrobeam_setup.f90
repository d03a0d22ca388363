!> From a validated scene to everything a run needs (scene -> discrete model in the data
!! flow of CONTRIBUTING.md, "Architecture"): the beam model, its contact points, its loads and its initial state.
!! Used by the program and by the verification drivers, so both run the same set-up.
module vibrobeam_setup
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use vibrobeam_kinds, only: dp, int64
   use vibrobeam_status, only: stat_failure, stat_numerical_failure
   use vibrobeam_text, only: real_text
   use vibrobeam_scene, only: scene_type, step_count, is_unset
   use vibrobeam_model, only: beam_model, build_model
   use vibrobeam_contact_set, only: contact_set, contact_value
   use vibrobeam_obstacles, only: build_contact_points
   use vibrobeam_loads, only: load_set, build_loads
   use vibrobeam_initial_state, only: mode_field, initial_velocity
   use vibrobeam_static, only: solve_static
   use vibrobeam_time_stepper, only: time_stepper
   use vibrobeam_velocity_stepper, only: velocity_stepper
   use vibrobeam_position_stepper, only: position_stepper
   use vibrobeam_state_record, only: state_record
   use vibrobeam_checkpoint, only: read_checkpoint
   use vibrobeam_restart_check, only: check_compatible
   use vibrobeam_contact_projector, only: contact_method_code
   use vibrobeam_compliant_law, only: rule_code
   use vibrobeam_reduction, only: reduced_basis, build_reduction, reduce_model, reduce_contacts, reduce_loads, &
                                  reduce_state, default_reduction_frequency
   implicit none
   private
   public :: prepared_scene, prepare_scene, start_stepper, start_time_stepper, reduction_cutoff, release_stepper

   type :: prepared_scene
      type(beam_model) :: model
      type(contact_set) :: contacts
      type(load_set) :: loads
      real(dp), allocatable :: u0(:)   !! initial displacement unknowns (dynamics)
      real(dp), allocatable :: v0(:)   !! initial velocity unknowns (dynamics)
      !> U^{-1} of the position scheme when the start continues an earlier state (a sweep's
      !! continuation); not allocated: the scheme's second-order start from u0, v0
      real(dp), allocatable :: u_previous0(:)
      logical :: resuming = .false.    !! continues the checkpoint of &initial from_file
      type(state_record) :: resume     !! that checkpoint
      real(dp) :: resume_time = 0      !! its time (s)
      !> &mesh reduction = 'craig-bampton' (dynamics): the steppers run on the reduced
      !! model, contact points, loads and initial state below, the recorder maps back
      logical :: reduced = .false.
      type(reduced_basis) :: reduction
      type(beam_model) :: reduced_model
      type(contact_set) :: reduced_contacts
      type(load_set) :: reduced_loads
      real(dp), allocatable :: q0(:), qv0(:)   !! initial reduced coordinates and velocities
   end type prepared_scene

contains

   !> Build model, contact points, loads and initial state of `scene` (already validated).
   !! stat = `stat_failure` with a message naming the input when the scene is
   !! inconsistent (obstacles that contradict each other, an initial displacement outside
   !! the obstacles, a checkpoint of &initial from_file that does not match);
   !! `stat_numerical_failure` when the static solve of `&initial displacement = 'static'`
   !! fails; `warnings` collects one line per warning.
   subroutine prepare_scene(scene, prepared, warnings, stat, errmsg)
      type(scene_type), intent(in) :: scene
      type(prepared_scene), intent(out) :: prepared
      character(len=:), allocatable, intent(inout) :: warnings
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      call build_model(scene%mesh%basis, scene%mesh%elements, scene%beam%length, scene%beam%rho_s(), scene%beam%ei(), &
                       prepared%model, stat, errmsg, &
                       boundary=scene%beam%boundary)
      if (stat /= 0) return
      call build_contact_points(scene%obstacles, prepared%model, prepared%contacts, warnings, stat, errmsg)
      if (stat /= 0) return
      call build_loads(scene%load, prepared%model, scene%beam%rho_s(), prepared%loads)
      if (scene%analysis%kind == 'dynamics' .and. len_trim(scene%initial%from_file) > 0) then
         call resume_from_file(scene, prepared, warnings, stat, errmsg)
         return
      end if
      call initial_displacement(scene, prepared, stat, errmsg)
      if (stat /= 0) return
      prepared%v0 = initial_velocity(scene%initial, prepared%model)
      ! a failed interpolation of the initial fields returns NaN (vibrobeam_lapack)
      if (.not. all(ieee_is_finite(prepared%u0)) .or. .not. all(ieee_is_finite(prepared%v0))) then
         stat = stat_numerical_failure
         errmsg = '&initial: the initial displacement or velocity is not finite (interpolation on the mesh failed)'
         return
      end if
      if (scene%analysis%kind == 'dynamics' .and. scene%mesh%reduction == 'craig-bampton') call reduce_scene(scene, &
         prepared, stat, errmsg)
   end subroutine prepare_scene

   !> The cut-off of the fixed-interface modes (rad/s): &mesh reduction_frequency, or its
   !! default from the forcing frequencies and dt (`default_reduction_frequency`).
   pure function reduction_cutoff(scene) result(cutoff)
      type(scene_type), intent(in) :: scene
      real(dp) :: cutoff
      real(dp) :: forcing(3)
      logical :: loaded(3)
      if (.not. is_unset(scene%mesh%reduction_frequency)) then
         cutoff = scene%mesh%reduction_frequency
         return
      end if
      forcing = [scene%load%distributed_frequency, scene%load%point_frequency, scene%load%base_frequency]
      loaded = [abs(scene%load%distributed) > 0, abs(scene%load%point_force) > 0, abs(scene%load%base_amplitude) > 0]
      cutoff = default_reduction_frequency(scene%time%dt, pack(forcing, loaded))
   end function reduction_cutoff

   !> The Craig-Bampton reduced model of a prepared scene (`vibrobeam_reduction`).
   subroutine reduce_scene(scene, prepared, stat, errmsg)
      type(scene_type), intent(in) :: scene
      type(prepared_scene), intent(inout) :: prepared
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      if (scene%mesh%reduction_modes > prepared%model%unknowns - prepared%contacts%count) then
         stat = stat_failure
         write (errmsg, '(a,i0,a,i0,a,i0,a,i0,a)') '&mesh reduction_modes = ', scene%mesh%reduction_modes, &
            ' is more than the J - m = ', prepared%model%unknowns - prepared%contacts%count, &
            ' fixed-interface modes of the mesh (J = ', prepared%model%unknowns, ' unknowns, m = ', &
            prepared%contacts%count, ' contact points)'
         return
      end if
      call build_reduction(prepared%model, prepared%contacts, reduction_cutoff(scene), scene%mesh%reduction_modes, &
                           prepared%reduction, stat, errmsg)
      if (stat /= 0) then
         errmsg = '&mesh reduction = ''craig-bampton'': '//trim(errmsg)
         stat = stat_numerical_failure
         return
      end if
      if (prepared%reduction%boundary + prepared%reduction%modes == 0) then
         stat = stat_failure
         errmsg = '&mesh reduction = ''craig-bampton'' keeps nothing: no contact point and no mode below '// &
                  'reduction_frequency = '//real_text(reduction_cutoff(scene))//' rad/s; raise it or give reduction_modes'
         return
      end if
      call reduce_model(prepared%model, prepared%reduction, prepared%reduced_model)
      call reduce_contacts(prepared%contacts, prepared%reduced_contacts)
      call reduce_loads(prepared%loads, prepared%reduction, prepared%reduced_loads)
      prepared%q0 = reduce_state(prepared%model, prepared%contacts, prepared%reduction, prepared%u0)
      prepared%qv0 = reduce_state(prepared%model, prepared%contacts, prepared%reduction, prepared%v0)
      prepared%reduced = .true.
   end subroutine reduce_scene

   !> The initial state of a run that continues the checkpoint of &initial from_file
   !! (docs/output.md, "Checkpoint and restart"): the file must match the scene in its
   !! model, time scheme, contact points and compliant stops; its checkpoint must match its
   !! checksum (one without a checksum, of vibrobeam 0.2.0, is continued with a warning);
   !! t_end must lie after the checkpoint; when the obstacle bounds changed, the state must
   !! satisfy the new ones.
   subroutine resume_from_file(scene, prepared, warnings, stat, errmsg)
      type(scene_type), intent(in) :: scene
      type(prepared_scene), intent(inout) :: prepared
      character(len=:), allocatable, intent(inout) :: warnings
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer(int64) :: steps
      logical :: same_bounds, verified
      real(dp) :: value
      character(len=:), allocatable :: file
      integer :: c
      file = trim(scene%initial%from_file)
      associate (contacts => prepared%contacts)
         call check_compatible(file, scene, contacts%x, contacts%lower, contacts%upper, same_bounds, stat, errmsg, &
                               stops=.true.)
         if (stat /= 0) return
         call read_checkpoint(file, prepared%resume, prepared%resume_time, stat, errmsg, verified)
         if (stat /= 0) then
            errmsg = '&initial from_file = '''//file//''': '//trim(errmsg)
            return
         end if
         if (.not. verified) warnings = warnings//'&initial from_file = '''//file//''': its checkpoint carries '// &
            'no checksum (written by vibrobeam 0.2.0): it is continued without a check that it is undamaged'// &
            new_line('a')
         allocate (prepared%u0(prepared%model%unknowns), prepared%v0(prepared%model%unknowns))
         call prepared%resume%get_reals('stepper.u', prepared%u0, stat, errmsg)
         if (stat == 0) call prepared%resume%get_reals('stepper.v', prepared%v0, stat, errmsg)
         if (stat == 0) call prepared%resume%get_int64('stepper.steps', steps, stat, errmsg)
         if (stat /= 0) then
            errmsg = '&initial from_file = '''//file//''': '//trim(errmsg)
            return
         end if
         if (step_count(scene) <= steps) then
            stat = stat_failure
            errmsg = '&time t_end = '//real_text(scene%time%t_end)//' s is not after the checkpoint of '''//file// &
                     ''' at t = '//real_text(steps*scene%time%dt)//' s (t_end is the end time of the continued run)'
            return
         end if
         prepared%resuming = .true.
         do c = 1, contacts%count
            if (same_bounds) exit
            value = contact_value(contacts, c, prepared%u0)
            if (value + 1e-12_dp*(abs(value) + prepared%model%length) < contacts%lower(c) .or. &
                value - 1e-12_dp*(abs(value) + prepared%model%length) > contacts%upper(c)) then
               stat = stat_failure
               errmsg = '&initial from_file = '''//file//''': the beam is at u = '//real_text(value)//' m at x = '// &
                        real_text(contacts%x(c))//' m, outside the changed obstacles there ['// &
                        real_text(contacts%lower(c))//', '//real_text(contacts%upper(c))//'] m'
               return
            end if
         end do
      end associate
   end subroutine resume_from_file

   !> The initial displacement of a dynamics run (zero, a mode, or the static equilibrium
   !! under the loads at t = 0); it must satisfy every obstacle (theory §1: u0 in K).
   subroutine initial_displacement(scene, prepared, stat, errmsg)
      type(scene_type), intent(in) :: scene
      type(prepared_scene), intent(inout) :: prepared
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      real(dp), allocatable :: reaction(:)
      real(dp) :: value
      integer :: c, iterations
      stat = 0
      errmsg = ''
      allocate (prepared%u0(prepared%model%unknowns), source=0.0_dp)
      if (scene%analysis%kind /= 'dynamics') return
      associate (model => prepared%model, contacts => prepared%contacts)
         select case (scene%initial%displacement)
         case ('mode')
            prepared%u0 = mode_field(model, scene%initial%displacement_mode, scene%initial%displacement_amplitude)
         case ('static')
            allocate (reaction(contacts%count))
            call solve_static(model, contacts, prepared%loads%at(0.0_dp), prepared%u0, reaction, iterations, stat, &
                              errmsg, scene%solver%contact_max_iterations)
            if (stat /= 0) then
               errmsg = '&initial displacement = ''static'': '//trim(errmsg)
               stat = stat_numerical_failure
               return
            end if
         end select
         do c = 1, contacts%count
            value = contact_value(contacts, c, prepared%u0)
            ! a static equilibrium sits on its obstacles up to round-off, relative to the
            ! beam's length (a floor at level 0 has no scale of its own)
            if (value + 1e-12_dp*(abs(value) + model%length) < contacts%lower(c) .or. &
                value - 1e-12_dp*(abs(value) + model%length) > contacts%upper(c)) then
               write (errmsg, '(a,g0.6,a,g0.6,a,g0.6,a,g0.6,a)') '&initial displacement_amplitude = ', &
                  scene%initial%displacement_amplitude, ' puts the beam at u = ', value, ' m at x = ', contacts%x(c), &
                  ' m, outside the obstacles there [', contacts%lower(c), ', '
               write (errmsg, '(a,g0.6,a)') trim(errmsg), contacts%upper(c), '] m'
               stat = stat_failure
               return
            end if
         end do
      end associate
   end subroutine initial_displacement

   !> A velocity stepper at t = 0 for a prepared scene, with the scene's time settings.
   subroutine start_stepper(scene, prepared, stepper, stat, errmsg)
      type(scene_type), intent(in) :: scene
      type(prepared_scene), intent(in) :: prepared
      type(velocity_stepper), intent(out) :: stepper
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      stepper%compliant_rule = rule_code(trim(scene%time%compliant_rule))
      if (prepared%reduced) then
         call stepper%init(prepared%reduced_model, prepared%reduced_contacts, prepared%reduced_loads, scene%time%dt, &
                           scene%time%theta, scene%time%gamma, scene%impact%restitution, scene%beam%rayleigh_mass, &
                              scene%beam%rayleigh_stiffness, &
                           scene%solver%contact_solver, prepared%q0, prepared%qv0, stat, errmsg)
      else
         call stepper%init(prepared%model, prepared%contacts, prepared%loads, scene%time%dt, scene%time%theta, scene%time%gamma, &
                           scene%impact%restitution, scene%beam%rayleigh_mass, scene%beam%rayleigh_stiffness, &
                              scene%solver%contact_solver, &
                           prepared%u0, prepared%v0, stat, errmsg)
      end if
      stepper%projector%max_iterations = scene%solver%contact_max_iterations
      stepper%projector%method = contact_method_code(trim(scene%solver%contact_method))
      stepper%compliant%method = trim(scene%solver%contact_method)
      if (scene%impact%separating_points == 'restitution') stepper%separating_restitution = scene%impact%restitution
   end subroutine start_stepper

   !> The stepper of the scene's scheme (&time scheme: 'velocity' or 'position') at t = 0,
   !! or at the checkpoint that the prepared scene continues.
   subroutine start_time_stepper(scene, prepared, stepper, stat, errmsg)
      type(scene_type), intent(in) :: scene
      type(prepared_scene), intent(in) :: prepared
      class(time_stepper), allocatable, intent(out) :: stepper
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      type(velocity_stepper), allocatable :: velocity
      type(position_stepper), allocatable :: position
      if (scene%time%scheme == 'position') then
         allocate (position)
         position%compliant_rule = rule_code(trim(scene%time%compliant_rule))
         if (prepared%reduced) then
            call position%init(prepared%reduced_model, prepared%reduced_contacts, prepared%reduced_loads, scene%time%dt, &
                               scene%time%theta, scene%impact%restitution, scene%beam%rayleigh_mass, &
                                  scene%beam%rayleigh_stiffness, &
                               scene%solver%contact_solver, prepared%q0, prepared%qv0, stat, errmsg)
         else
            call position%init(prepared%model, prepared%contacts, prepared%loads, scene%time%dt, scene%time%theta, &
                               scene%impact%restitution, scene%beam%rayleigh_mass, scene%beam%rayleigh_stiffness, &
                                  scene%solver%contact_solver, &
                               prepared%u0, prepared%v0, stat, errmsg)
         end if
         position%projector%max_iterations = scene%solver%contact_max_iterations
         position%projector%method = contact_method_code(trim(scene%solver%contact_method))
         position%compliant%method = trim(scene%solver%contact_method)
         if (stat == 0 .and. allocated(prepared%u_previous0)) then
            ! the state of an earlier run carried on (docs/sweeps.md, "Continuation")
            position%u_previous = prepared%u_previous0
            position%v = (position%u - position%u_previous)/scene%time%dt
         end if
         call move_alloc(position, stepper)
      else
         allocate (velocity)
         call start_stepper(scene, prepared, velocity, stat, errmsg)
         call move_alloc(velocity, stepper)
      end if
      if (stat == 0 .and. prepared%resuming) call stepper%restore_state(prepared%resume, stat, errmsg)
   end subroutine start_time_stepper

   !> Deallocate a stepper of `start_time_stepper`. gfortran 12 frees only the first of
   !! the symmetric_band components of time_stepper (mass) when a class(time_stepper) whose
   !! dynamic type is a scheme's stepper is deallocated: stiffness and iteration_matrix,
   !! (kd + 1) J doubles each, were lost once per stepper, so once per point of a sweep
   !! (valgrind: 2 blocks "definitely lost" for each); they are freed here first.
   subroutine release_stepper(stepper)
      class(time_stepper), allocatable, intent(inout) :: stepper
      if (.not. allocated(stepper)) return
      if (allocated(stepper%stiffness%lower)) deallocate (stepper%stiffness%lower)
      if (allocated(stepper%iteration_matrix%lower)) deallocate (stepper%iteration_matrix%lower)
      deallocate (stepper)
   end subroutine release_stepper
end module vibrobeam_setup
