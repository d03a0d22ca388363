!> The tangent of one step of the velocity scheme (`linearise_step`, the map the Lyapunov
!! exponent and the periodic analysis's monodromy multiply) against central differences of
!! the step itself (issue 20, item 3; docs/method.md, "Compliant stops" and "Periodic orbits
!! by shooting").
!!
!! The scene is marched until a step of the kind asked for (`springs`: a compliant stop
!! engaged at the step's end; `held`: also a rigid point held in it), and x = (U, V) is the
!! state before that step. From x, a stepper restored from the checkpoint record of the
!! marching before that step takes the step and its tangent is applied to the 2 J unit
!! perturbations (columns T_j); such steppers set to x +- h_j e_j take the same step, D_j(h) = (Phi(x + h_j e_j) - Phi(x - h_j e_j))/(2 h_j). Column by
!! column, in the energy norm G at the forcing frequency (per unit perturbation, ||e_j||_G
!! = 1 with h_j = 1e-5 ||x||_G/sqrt(G_jj), which keeps every spring and held point as it
!! was): a central difference errs by c h^2 (the map's third derivative) plus the
!! round-off of its two steps over 2 h; D(h/2) then errs by a quarter of the first, so
!! |T_j - D_j(h/2)| <= |D_j(h) - D_j(h/2)|/3 (Richardson) + 2 noise/h, noise = 8 eps rho
!! ||Phi(x)|| (a step's componentwise round-off weighed by rho, test_periodic_linear); a
!! factor 2 is allowed beside it. The spring slopes are what it tests: 1 % off in either of
!! them (b = df/dp0 or a = df/dp1) moves the tangent far beyond that bound.
!! Usage: test_step_tangent SCENE.nml springs|held
program test_step_tangent
   use vibrobeam_kinds, only: dp, int64
   use vibrobeam_scene, only: scene_type, forcing_of
   use vibrobeam_problem, only: run_problem, new_stepper, problem_stepper_settings
   use vibrobeam_time_stepper, only: time_stepper, dynamic_state
   use vibrobeam_stepper_factory, only: new_time_stepper, release_stepper, linearise_step
   use vibrobeam_state_record, only: state_record
   use vibrobeam_periodic_reference, only: energy_gram, energy_norm, cancellation
   use vibrobeam_test_support, only: test_counter, read_test_scene, prepare_test_scene
   implicit none
   type(test_counter) :: t
   type(scene_type) :: scene
   type(run_problem) :: prepared
   class(time_stepper), allocatable :: marching
   type(state_record) :: before
   character(len=512) :: path, errmsg
   character(len=16) :: kind_asked
   character(len=:), allocatable :: load
   real(dp), allocatable :: x(:), image(:), gram(:, :), du(:, :), dv(:, :), tangent(:, :), d_h(:), d_half(:), h(:)
   real(dp) :: omega, phase, noise, error, bound, worst, scale
   integer :: n, m, j, stat, found
   integer(int64) :: step

   call get_command_argument(1, path)
   call get_command_argument(2, kind_asked)
   scene = read_test_scene(trim(path))
   call prepare_test_scene(scene, prepared)
   load = forcing_of(scene, omega, phase)
   n = prepared%system%model%unknowns
   m = 2*n
   gram = energy_gram(prepared, omega)

   ! ---- march until a step of the kind asked for; x is the state before it ----
   call new_stepper(scene, prepared, marching, stat, errmsg)
   if (stat /= 0) error stop 'new_stepper'
   found = 0
   do step = 1, 2000000
      x = [marching%u, marching%v]
      call marching%step(stat, errmsg)
      if (stat /= 0) error stop 'the marching step failed'
      if (wanted(marching)) then
         found = 1
         exit
      end if
   end do
   call release_stepper(marching)
   call t%check_true('a step of the kind asked for ('//trim(kind_asked)//') was found', found == 1)
   if (found == 0) call t%finish('test_step_tangent')
   ! the stepper before that step, as a checkpoint holds it (its step number, so the loads
   ! of the step are those of the marching): each evaluation below restores it
   call new_stepper(scene, prepared, marching, stat, errmsg)
   do while (marching%steps < step - 1)
      call marching%step(stat, errmsg)
   end do
   call marching%save_state(before)
   call release_stepper(marching)
   write (*, '(a,i0,a)') 'the step from step ', step - 1, ' ('//trim(kind_asked)//')'

   ! ---- the tangent of that step on the 2 J unit perturbations ----
   allocate (du(n, m), dv(n, m), source=0.0_dp)
   do j = 1, n
      du(j, j) = 1
      dv(j, n + j) = 1
   end do
   image = one_step(x, du, dv)
   allocate (tangent(m, m))
   tangent(1:n, :) = du
   tangent(n + 1:, :) = dv
   scale = energy_norm(gram, x)
   noise = 8*epsilon(1.0_dp)*cancellation(gram, image)*energy_norm(gram, image)
   allocate (h(m))
   h = [(1e-5_dp*scale/sqrt(gram(j, j)), j=1, m)]

   ! ---- column by column against central differences ----
   worst = 0
   do j = 1, m
      d_h = central(j, h(j))
      d_half = central(j, 0.5_dp*h(j))
      ! per unit perturbation in the energy norm: ||e_j||_G = sqrt(G_jj)
      error = energy_norm(gram, tangent(:, j) - d_half)/sqrt(gram(j, j))
      bound = 2*(energy_norm(gram, d_h - d_half)/3 + 2*noise/(0.5_dp*h(j)))/sqrt(gram(j, j))
      worst = max(worst, error/bound)
      call t%check_close('tangent column against central differences (energy norm, per unit perturbation)', &
                         error, 0.0_dp, bound, scale=1.0_dp)
   end do
   write (*, '(a,es10.3,a,i0,a)') 'largest error / bound ', worst, ' over ', m, ' columns'
   call t%finish('test_step_tangent')

contains

   !> The step asked for: a spring engaged at its end (and a rigid point held in it).
   logical function wanted(stepper)
      class(time_stepper), intent(in) :: stepper
      integer :: k
      logical :: held
      wanted = .false.
      if (stepper%contacts%springs%count == 0) return
      if (.not. any(stepper%compliant%p1 > 1e-3_dp*maxval(abs(stepper%contacts%springs%level)))) return
      held = .false.
      do k = 1, stepper%report%active_count
         if (abs(stepper%report%impulse(k)) > 0) held = .true.
      end do
      wanted = kind_asked == 'springs' .or. held
   end function wanted

   !> Phi(x) of the step from the stepper before it (`before`) set to x, and its tangent
   !! applied to (du, dv).
   function one_step(state, du, dv) result(after)
      real(dp), intent(in) :: state(:)
      real(dp), intent(inout), optional :: du(:, :), dv(:, :)
      real(dp), allocatable :: after(:)
      class(time_stepper), allocatable :: stepper
      type(dynamic_state) :: start
      integer :: status
      start%u = state(1:n)
      start%v = state(n + 1:)
      call new_time_stepper(prepared%system, problem_stepper_settings(scene, prepared), start, stepper, status, errmsg, &
                             resume=before)
      if (status /= 0) error stop 'new_time_stepper'
      stepper%u = state(1:n)
      stepper%v = state(n + 1:)
      call stepper%step(status, errmsg)
      if (status /= 0) error stop 'the step failed'
      after = [stepper%u, stepper%v]
      if (present(du)) then
         call linearise_step(stepper, du, dv, status, errmsg)
         call t%check_true('the step is linearised', status == 0, trim(errmsg))
      end if
      call release_stepper(stepper)
   end function one_step

   !> (Phi(x + h e_j) - Phi(x - h e_j))/(2 h), with the perturbation the arithmetic made.
   function central(j, step_size) result(d)
      integer, intent(in) :: j
      real(dp), intent(in) :: step_size
      real(dp), allocatable :: d(:), plus(:), minus(:)
      allocate (plus, source=x)
      allocate (minus, source=x)
      plus(j) = plus(j) + step_size
      minus(j) = minus(j) - step_size
      d = (one_step(plus) - one_step(minus))/(plus(j) - minus(j))
   end function central
end program test_step_tangent
