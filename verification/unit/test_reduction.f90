!> Unit test of the Craig-Bampton reduced model (`vibrobeam_reduction`, &mesh reduction).
!! u = eps/2; kappa(A) the 2-norm condition number of a symmetric positive definite A,
!! computed here from its extreme eigenvalues (LAPACK dsygv on the dense matrix).
!!
!! 1. All modes kept (k = J - m): T is a square, invertible change of coordinates, so the
!!    reduced model is the full one in other coordinates. Both are stepped 400 steps by the
!!    velocity scheme (theta = 1/2, a tip stop hit several times, e = 0.7); U = T q is
!!    compared with U at every step. Bound: each step of either model is, in exact
!!    arithmetic, non-expansive in its energy norm (the trapezoidal step is an isometry of
!!    the energy norm, the contact projection a projection in the metric of W), so round-off
!!    adds up at most linearly: after n steps |U - T q| <= n (J + r) u (kappa(W) +
!!    kappa(T) kappa(W_r)) max|U|, a solve with W leaving a relative error (bandwidth + 1)
!!    u kappa(W) <= J u kappa(W), and kappa(T) converting errors of q into errors of U.
!! 2. Static condensation (k = 0) reproduces the full static solution of a load at the
!!    boundary unknowns, F = H^T f: then T^T F = Psi^T H^T f = S^-1 H K^-1 H^T f = f and
!!    T K_r^-1 T^T F = Psi S f = K^-1 H^T f = K^-1 F, exactly. The full solution comes from a
!!    band Cholesky solve of K (not the flexibility that builds Psi); tolerance
!!    10 J u (kappa(K) + kappa(S)) relative, both bases, two contact points.
!! 3. Frequencies of the reduced model converge from above: its space is a subspace of the
!!    full one (Rayleigh-Ritz), and adding modes enlarges it, so omega_i(k) >= omega_i(full)
!!    and omega_i(k) is non-increasing in k; with every mode kept they are equal. Eigenvalues
!!    of the dense pencils by dsygv, each with an absolute error of about J u lambda_max:
!!    tolerance 10 J u lambda_max/lambda_i relative on lambda_i.
program test_reduction
   use vibrobeam_kinds, only: dp, output_unit
   use vibrobeam_scene, only: scene_type, obstacle_type
   use vibrobeam_scene_rules, only: validate_scene
   use vibrobeam_problem, only: run_problem, new_stepper
   use vibrobeam_time_stepper, only: time_stepper
   use vibrobeam_band, only: band_cholesky, band_factor, band_solve, band_to_dense
   use vibrobeam_contact_set, only: contact_value
   use vibrobeam_lapack, only: dsygv, dpotrf, dpotrs
   use vibrobeam_test_support, only: test_counter, prepare_test_scene
   implicit none
   real(dp), parameter :: u = epsilon(1.0_dp)/2
   type(test_counter) :: counter

   call all_modes_kept()
   call static_condensation('hermite')
   call static_condensation('bspline')
   call frequencies_from_above('hermite')
   call frequencies_from_above('bspline')
   call counter%finish('test_reduction')

contains

   !> A cantilever of N elements with obstacles: below the tip at -0.02 (and, with
   !! `middle`, below and above the middle node far away so that it is a contact point).
   function beam_scene(basis, elements, middle) result(scene)
      character(len=*), intent(in) :: basis
      integer, intent(in) :: elements
      logical, intent(in) :: middle
      type(scene_type) :: scene
      integer :: stat
      character(len=256) :: errmsg
      scene%mesh%basis = basis
      scene%mesh%elements = elements
      scene%time%dt = 1e-3_dp
      scene%time%t_end = 0.4_dp
      scene%impact%restitution = 0.7_dp
      scene%initial%velocity = 'mode'
      scene%initial%velocity_amplitude = -1
      scene%load%point_position = 1
      if (middle) then
         scene%obstacles = [obstacle_type(side='below', x_from=1, x_to=1, level_from=-0.02_dp, level_to=-0.02_dp), &
                            obstacle_type(side='below', x_from=0.5_dp, x_to=0.5_dp, level_from=-1, level_to=-1)]
      else
         scene%obstacles = [obstacle_type(side='below', x_from=1, x_to=1, level_from=-0.02_dp, level_to=-0.02_dp)]
      end if
      call validate_scene(scene, stat, errmsg)
      if (stat /= 0) then
         write (output_unit, '(a)') trim(errmsg)
         error stop 'test_reduction: invalid test scene'
      end if
   end function beam_scene

   !> The scene reduced with `modes` fixed-interface modes.
   subroutine reduced_scene(scene, modes, prepared)
      type(scene_type), intent(in) :: scene
      integer, intent(in) :: modes
      type(run_problem), intent(out) :: prepared
      type(scene_type) :: reduced
      reduced = scene
      reduced%mesh%reduction = 'craig-bampton'
      reduced%mesh%reduction_modes = modes
      call prepare_test_scene(reduced, prepared)
   end subroutine reduced_scene

   !> Eigenvalues (ascending) of the pencil (a, b) (b = identity when absent).
   function eigenvalues(a, b) result(lambda)
      real(dp), intent(in) :: a(:,:)
      real(dp), intent(in), optional :: b(:,:)
      real(dp) :: lambda(size(a, 1))
      real(dp) :: aa(size(a, 1), size(a, 1)), bb(size(a, 1), size(a, 1)), work(64*size(a, 1))
      integer :: n, info, i
      n = size(a, 1)
      aa = a
      if (present(b)) then
         bb = b
      else
         bb = 0
         do i = 1, n
            bb(i, i) = 1
         end do
      end if
      call dsygv(1, 'N', 'L', n, aa, n, bb, n, lambda, work, size(work), info)
      if (info /= 0) error stop 'test_reduction: dsygv failed'
   end function eigenvalues

   real(dp) function condition(a)
      real(dp), intent(in) :: a(:,:)
      real(dp) :: lambda(size(a, 1))
      lambda = eigenvalues(a)
      condition = lambda(size(a, 1))/lambda(1)
   end function condition

   subroutine all_modes_kept()
      type(scene_type) :: scene
      type(run_problem) :: full, reduced
      class(time_stepper), allocatable :: full_stepper, reduced_stepper
      integer :: stat, n, steps, impacts, j, r
      character(len=256) :: errmsg
      real(dp) :: difference, largest, bound, kappa_w, kappa_wr, kappa_t
      real(dp), allocatable :: t(:,:)
      scene = beam_scene('hermite', 6, .false.)
      call prepare_test_scene(scene, full)
      j = full%model%unknowns
      call reduced_scene(scene, j - 1, reduced)
      r = reduced%system%model%unknowns
      call counter%check_true('all modes: r = J', r == j)
      call new_stepper(scene, full, full_stepper, stat, errmsg)
      if (stat == 0) call new_stepper(scene, reduced, reduced_stepper, stat, errmsg)
      if (stat /= 0) error stop 'test_reduction: stepper set-up failed'
      t = reduced%reduction%transform
      kappa_w = condition(band_to_dense(full_stepper%iteration_matrix))
      kappa_wr = condition(band_to_dense(reduced_stepper%iteration_matrix))
      kappa_t = sqrt(condition(matmul(transpose(t), t)))
      steps = 400
      difference = 0
      largest = 0
      impacts = 0
      do n = 1, steps
         call full_stepper%step(stat, errmsg)
         if (stat == 0) call reduced_stepper%step(stat, errmsg)
         if (stat /= 0) error stop 'test_reduction: a step failed'
         difference = max(difference, maxval(abs(full_stepper%u - matmul(t, reduced_stepper%u))))
         largest = max(largest, maxval(abs(full_stepper%u)))
         if (full_stepper%report%active_count > 0) impacts = impacts + 1
      end do
      bound = steps*(j + r)*u*(kappa_w + kappa_t*kappa_wr)
      write (output_unit, '(a,i0,a,es10.3,a,es10.3,a,es9.2,a,es9.2,a,es9.2)') 'all modes kept: ', impacts, &
         ' steps with contact, max |U - T q| = ', difference, ' (bound ', bound*largest, '); kappa(W) ', kappa_w, &
         ', kappa(W_r) ', kappa_wr, ', kappa(T) ', kappa_t
      call counter%check_true('all modes: the stop is hit', impacts >= 3)
      call counter%check_close('all modes: U = T q at every step', difference, 0.0_dp, bound, largest)
      call counter%check_close('all modes: same energy', reduced_stepper%kinetic_energy() + &
                               reduced_stepper%elastic_energy(), full_stepper%kinetic_energy() + &
                               full_stepper%elastic_energy(), bound)
   end subroutine all_modes_kept

   subroutine static_condensation(basis)
      character(len=*), intent(in) :: basis
      type(scene_type) :: scene
      type(run_problem) :: full, reduced
      type(band_cholesky) :: factor
      real(dp), allocatable :: force(:), exact(:), projected(:), stiffness_r(:,:), y(:,:), t(:,:)
      real(dp) :: s(2, 2)
      real(dp) :: f(2), tolerance
      integer :: stat, c, a, m, info
      character(len=256) :: errmsg
      scene = beam_scene(basis, 10, .true.)
      call prepare_test_scene(scene, full)
      call reduced_scene(scene, 0, reduced)
      m = reduced%reduction%boundary
      call counter%check_true(basis//' static: two boundary unknowns, no mode', m == 2 .and. &
                              reduced%system%model%unknowns == 2)
      f = [1.0_dp, -0.5_dp]
      allocate (force(full%model%unknowns), source=0.0_dp)
      do c = 1, m
         do a = 1, 4
            if (full%contacts%dofs(a, c) /= 0) force(full%contacts%dofs(a, c)) = &
               force(full%contacts%dofs(a, c)) + full%contacts%weights(a, c)*f(c)
         end do
      end do
      exact = force
      call band_factor(full%model%stiffness, factor, stat, errmsg)
      if (stat /= 0) error stop 'test_reduction: factor of K failed'
      call band_solve(factor, exact)
      t = reduced%reduction%transform
      projected = matmul(force, t)
      stiffness_r = band_to_dense(reduced%system%model%stiffness)
      s = stiffness_r
      call dpotrf('L', m, s, m, info)
      y = reshape(projected, [m, 1])
      call dpotrs('L', m, 1, s, m, y, m, info)
      if (info /= 0) error stop 'test_reduction: reduced static solve failed'
      tolerance = 10*full%model%unknowns*u*(condition(band_to_dense(full%model%stiffness)) + condition(stiffness_r))
      do c = 1, m
         call counter%check_close(basis//' static: T^T H^T f = f', projected(c), f(c), tolerance, 1.0_dp)
      end do
      do c = 1, full%model%unknowns
         call counter%check_close(basis//' static: T K_r^-1 T^T F = K^-1 F', dot_product(t(c, :), y(:, 1)), &
                                  exact(c), tolerance, maxval(abs(exact)))
      end do
      do c = 1, m
         call counter%check_close(basis//' static: contact displacement', contact_value(full%contacts, c, exact), &
                                  y(c, 1), tolerance, maxval(abs(exact)))
      end do
   end subroutine static_condensation

   subroutine frequencies_from_above(basis)
      character(len=*), intent(in) :: basis
      type(scene_type) :: scene
      type(run_problem) :: full, reduced
      real(dp), allocatable :: lambda_full(:), lambda(:), previous(:)
      integer :: counts(6), k, i, j, m, r
      real(dp) :: tolerance
      character(len=80) :: name
      scene = beam_scene(basis, 16, .true.)
      call prepare_test_scene(scene, full)
      j = full%model%unknowns
      lambda_full = eigenvalues(band_to_dense(full%model%stiffness), band_to_dense(full%model%mass))
      m = 2
      counts = [0, 1, 2, 4, 8, j - m]
      allocate (previous(j), source=huge(1.0_dp))
      do k = 1, size(counts)
         call reduced_scene(scene, counts(k), reduced)
         r = reduced%system%model%unknowns
         lambda = eigenvalues(band_to_dense(reduced%system%model%stiffness), band_to_dense(reduced%system%model%mass))
         write (output_unit, '(a,i3,a,3es12.4)') basis//' modes kept', counts(k), &
            ': relative excess of omega_1..3 over the full model ', &
            (sqrt(lambda(i)/lambda_full(i)) - 1, i=1, min(3, r))
         do i = 1, r
            tolerance = 10*j*u*max(lambda(r), lambda_full(j))/lambda_full(i)
            write (name, '(a,i0,a,i0)') basis//' omega_', i, ' from above, modes ', counts(k)
            call counter%check_true(trim(name), lambda(i) >= lambda_full(i)*(1 - tolerance))
            write (name, '(a,i0,a,i0)') basis//' omega_', i, ' non-increasing, modes ', counts(k)
            call counter%check_true(trim(name), lambda(i) - previous(i) <= tolerance*previous(i))
            if (counts(k) == j - m) then
               write (name, '(a,i0,a)') basis//' omega_', i, ' with every mode kept'
               call counter%check_close(trim(name), lambda(i), lambda_full(i), tolerance)
            end if
         end do
         previous(1:r) = lambda
      end do
   end subroutine frequencies_from_above
end program test_reduction
