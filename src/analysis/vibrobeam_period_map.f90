!> The period map of a forced scene and its Jacobian (docs/method.md, "Periodic orbits by
!! shooting"): x = (U, V) at phase 0 of the forcing, in the coordinates the stepper steps
!! (the mesh's unknowns, or the reduced model's), goes to the state after the steps of k
!! forcing periods, Phi(x). One evaluation is one run of the run loop (`advance`, the
!! same loop as a dynamics run) over those steps from a new stepper at step 0; its
!! Jacobian, the monodromy, is the product of the steps' derivatives (`linearise_step`,
!! carried along in the same run, exact for the discrete map) or forward differences of
!! Phi (one more run per unknown).
module vibrobeam_period_map
   use vibrobeam_kinds, only: dp, int64
   use vibrobeam_status, only: outcome_ok
   use vibrobeam_scene, only: scene_type
   use vibrobeam_problem, only: run_problem, problem_stepper_settings
   use vibrobeam_time_stepper, only: time_stepper, dynamic_state, energy_norm
   use vibrobeam_stepper_factory, only: new_time_stepper, release_stepper, linearise_step
   use vibrobeam_recorder, only: dynamics_recorder
   use vibrobeam_run_loop, only: advance, run_hooks
   implicit none
   private
   public :: period_map, map_image, jacobian_none, jacobian_linearised, jacobian_differences, difference_step
   public :: difference_fraction

   !> How `evaluate` takes the Jacobian: not at all, by the linearised steps, by forward
   !! differences.
   integer, parameter :: jacobian_none = 0, jacobian_linearised = 1, jacobian_differences = 2

   !> The relative size of a forward difference's perturbation, in the energy norm of
   !! the state (`difference_step`): sqrt(eps), which balances the round-off eps/h of a
   !! difference quotient against the h of a curved (compliant) map; on a piece of the
   !! piecewise-affine rigid map a difference is exact but for that round-off.
   real(dp), parameter :: difference_fraction = sqrt(epsilon(1.0_dp))

   !> The map of one orbit: the steps of `steps` = k P (P steps per forcing period) from
   !! a state at phase 0. `omega` weighs U in the energy norm of the state.
   type :: period_map
      integer(int64) :: steps = 0            !! steps of one orbit, k P
      integer :: unknowns = 0                !! unknowns of the stepped system (J, or r reduced); x has twice as many
      real(dp) :: omega = 0                  !! forcing frequency (rad/s)
      integer(int64) :: steps_taken = 0      !! every step of every evaluation so far (the cost)
   contains
      procedure :: evaluate
      procedure :: norm => state_norm
      procedure :: weights => diagonal_weights
   end type period_map

   !> Phi(x) and what came with it.
   type :: map_image
      real(dp), allocatable :: state(:)          !! Phi(x) = (U, V) after the orbit's steps (2 unknowns)
      real(dp), allocatable :: jacobian(:, :)    !! (2 unknowns, 2 unknowns) when asked: dPhi/dx
      real(dp), allocatable :: tip(:, :)         !! (2, 0:steps) u (m) and v (m/s) at the tip after each step
      !> (unknowns) the tip's row on the stepper's unknowns: u_tip = tip_row . U, v_tip = tip_row . V
      real(dp), allocatable :: tip_row(:)
      !> the smallest clearance to the obstacles over the start and every step
      !! (`smallest_clearance`, m; huge without obstacles): a sampled minimum
      real(dp) :: minimum_gap = huge(1.0_dp)
      integer :: status = outcome_ok             !! how the run loop ended (outcome_ok, _failed, _interrupted)
      character(len=512) :: failure = ''         !! why it failed ('step n (t = ...): reason')
   end type map_image

   !> What the run loop does after each step of an evaluation: keep the tip's u and v and
   !! the smallest clearance to the obstacles so far, and carry the perturbations (du, dv)
   !! through the step's derivative.
   type, extends(run_hooks) :: orbit_tracker
      logical :: linearised = .false.
      real(dp), allocatable :: du(:, :), dv(:, :)   !! (unknowns, 2 unknowns)
      real(dp), allocatable :: tip(:, :)            !! (2, 0:steps)
      real(dp) :: minimum_gap = huge(1.0_dp)        !! (m) over the steps so far
   contains
      procedure :: after_step => track_step
   end type orbit_tracker

contains

   !> Phi(x) (and its Jacobian by `jacobian`, one of jacobian_none, _linearised,
   !! _differences) in `image`. A step that fails (a contact solver without convergence, a
   !! state no longer finite) or an interruption ends the evaluation with image%status
   !! saying so. stat /= 0: the stepper could not be made or a step could not be
   !! linearised (errmsg).
   recursive subroutine evaluate(self, scene, prepared, x, jacobian, image, stat, errmsg)
      class(period_map), intent(inout) :: self
      type(scene_type), intent(in) :: scene
      type(run_problem), intent(in) :: prepared
      real(dp), intent(in) :: x(:)                !! (U, V) at phase 0
      integer, intent(in) :: jacobian
      type(map_image), intent(out) :: image
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      class(time_stepper), allocatable :: stepper
      type(dynamics_recorder) :: recorder
      type(orbit_tracker) :: tracker
      type(dynamic_state) :: start
      integer :: n, j
      n = self%unknowns
      start%u = x(1:n)
      start%v = x(n + 1:2*n)
      call new_time_stepper(prepared%system, problem_stepper_settings(scene, prepared), start, stepper, stat, errmsg)
      if (stat /= 0) return
      call recorder%init(scene, stepper, prepared, self%steps, write_rows=.false.)
      allocate (tracker%tip(2, 0:self%steps))
      call recorder%observe(stepper)
      tracker%tip(:, 0) = recorder%events%observed(1, :)
      image%tip_row = recorder%observed_row(1, n)
      tracker%minimum_gap = stepper%smallest_clearance(stepper%u)
      tracker%linearised = jacobian == jacobian_linearised
      if (tracker%linearised) then
         allocate (tracker%du(n, 2*n), tracker%dv(n, 2*n), source=0.0_dp)
         do j = 1, n
            tracker%du(j, j) = 1
            tracker%dv(j, n + j) = 1
         end do
      end if
      call advance(stepper, recorder, prepared%model, self%steps, image%status, image%failure, stat, errmsg, tracker)
      self%steps_taken = self%steps_taken + stepper%steps
      image%state = [stepper%u, stepper%v]
      call move_alloc(tracker%tip, image%tip)
      image%minimum_gap = tracker%minimum_gap
      call release_stepper(stepper)
      if (stat /= 0 .or. image%status /= outcome_ok) return
      select case (jacobian)
      case (jacobian_linearised)
         allocate (image%jacobian(2*n, 2*n))
         image%jacobian(1:n, :) = tracker%du
         image%jacobian(n + 1:2*n, :) = tracker%dv
      case (jacobian_differences)
         call differences(image)
      end select

   contains

      !> Forward differences (Phi(x + h_j e_j) - Phi(x))/h_j, column by column: each
      !! column an evaluation of its own (its own stepper, nothing shared but the read-only
      !! scene and problem), run on the threads of this process (OpenMP, as a sweep's tasks;
      !! OMP_NUM_THREADS or every core), so the Jacobian does not depend on the number of
      !! threads, bit for bit. A column that fails is reported as the serial loop would
      !! (the first in column order); the steps of every column run count in steps_taken.
      recursive subroutine differences(image)
         type(map_image), intent(inout) :: image
         real(dp) :: h(2*n)
         integer :: column_stat(2*n), column_status(2*n)
         integer(int64) :: column_steps(2*n)
         character(len=len(image%failure)), allocatable :: reasons(:)
         character(len=512), allocatable :: messages(:)
         character(len=*), parameter :: prefix = 'a finite difference of the period map: '
         h = difference_step(self, prepared, x, image%state)
         allocate (image%jacobian(2*n, 2*n), reasons(2*n), messages(2*n))
         column_stat = 0
         column_status = outcome_ok
         column_steps = 0
         !$omp parallel do schedule(dynamic, 1) default(shared) private(j)
         do j = 1, 2*n
            block
               type(period_map) :: column_map
               type(map_image) :: shifted
               real(dp), allocatable :: moved(:)
               column_map = self
               column_map%steps_taken = 0
               moved = x
               moved(j) = moved(j) + h(j)
               call column_map%evaluate(scene, prepared, moved, jacobian_none, shifted, column_stat(j), messages(j))
               column_steps(j) = column_map%steps_taken
               if (column_stat(j) == 0) then
                  column_status(j) = shifted%status
                  reasons(j) = shifted%failure
                  ! the step actually taken (x + h rounds h)
                  if (shifted%status == outcome_ok) &
                     image%jacobian(:, j) = (shifted%state - image%state)/(moved(j) - x(j))
               end if
            end block
         end do
         !$omp end parallel do
         self%steps_taken = self%steps_taken + sum(column_steps)
         do j = 1, 2*n
            if (column_stat(j) /= 0) then
               stat = column_stat(j)
               errmsg = messages(j)
               return
            end if
            if (column_status(j) /= outcome_ok) then
               image%status = column_status(j)
               ! (the reason cut to what the field holds, the prefix included)
               image%failure = prefix//reasons(j)(1:len(image%failure) - len(prefix))
               return
            end if
         end do
      end subroutine differences
   end subroutine evaluate

   !> After each step: the tip's u and v, the smallest clearance, and the perturbations
   !! through the step.
   subroutine track_step(self, stepper, recorder, step, stat, errmsg)
      class(orbit_tracker), intent(inout) :: self
      class(time_stepper), intent(in) :: stepper
      type(dynamics_recorder), intent(inout) :: recorder
      integer(int64), intent(in) :: step
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      stat = 0
      errmsg = ''
      self%tip(:, step) = recorder%events%observed(1, :)
      self%minimum_gap = min(self%minimum_gap, stepper%smallest_clearance(stepper%u))
      if (self%linearised) call linearise_step(stepper, self%du, self%dv, stat, errmsg)
   end subroutine track_step

   !> The energy norm of x = (U, V) at the forcing frequency (`vibrobeam_time_stepper`'s
   !! energy_norm, J^(1/2); per unit mass with k2).
   real(dp) function state_norm(self, prepared, x)
      class(period_map), intent(in) :: self
      type(run_problem), intent(in) :: prepared
      real(dp), intent(in) :: x(:)
      state_norm = energy_norm(prepared%system%model%mass, prepared%system%model%stiffness, self%omega, &
                               x(1:self%unknowns), x(self%unknowns + 1:2*self%unknowns))
   end function state_norm

   !> The perturbation of each component of x for a forward difference: difference_fraction
   !! of the larger energy norm of x and Phi(x) (1 when both are 0), over the square root
   !! of the component's diagonal weight in that norm (K + omega^2 M for U, M for V), so
   !! every perturbation moves the state by the same share of its energy.
   function difference_step(self, prepared, x, image) result(h)
      class(period_map), intent(in) :: self
      type(run_problem), intent(in) :: prepared
      real(dp), intent(in) :: x(:), image(:)
      real(dp) :: h(size(x)), scale
      scale = max(self%norm(prepared, x), self%norm(prepared, image))
      if (scale <= 0) scale = 1
      h = difference_fraction*scale/self%weights(prepared)
   end function difference_step

   !> Of each unknown of x = (U, V) the square root of its diagonal weight in the energy
   !! norm at the map's frequency (K + omega^2 M for U, M for V): the scale of a difference
   !! step, of the continuation's coordinates and of the autonomous orbit's system.
   function diagonal_weights(self, prepared) result(w)
      class(period_map), intent(in) :: self
      type(run_problem), intent(in) :: prepared
      real(dp) :: w(2*self%unknowns)
      associate (model => prepared%system%model, n => self%unknowns)
         w(1:n) = sqrt(model%stiffness%lower(1, 1:n) + self%omega**2*model%mass%lower(1, 1:n))
         w(n + 1:2*n) = sqrt(model%mass%lower(1, 1:n))
      end associate
   end function diagonal_weights
end module vibrobeam_period_map
