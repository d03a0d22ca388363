!> Dynamics of beams on other end supports (issue 18, item 1): rigid-body motions and
!! flexible modes stepped by both schemes, against the exact discrete solution of each
!! scheme with theta = 1/2 (energy conservation through impacts with e = 1 on a beam with
!! rigid-body motions: verification.energy_elastic_free_free).
!!
!! Free motion (no obstacle, no damping), for free-free (two rigid-body motions),
!!    sliding-free (one), pinned-pinned with rotational end springs and a cantilever with a
!!    tip spring, Hermite and B-splines: released in the first flexible mode phi (its
!!    discrete eigenvector, `compute_modes`) with amplitude a, plus a rigid-body velocity
!!    b r (r the rigid modes). The velocity scheme's theta = 1/2 rule maps (omega U, V) of
!!    a mode by a rotation of angle phi_dt, tan(phi_dt/2) = omega dt/2 (the Cayley
!!    transform of a skew matrix), and moves a rigid-body motion at constant velocity, so
!!    after n steps
!!
!!        U_n = a cos(n phi_dt) phi + n dt b r     exactly (theory §3).
!!
!!    The position scheme (theory §4), (1 + c) u^{n+1} - 2 u^n + (1 + c) u^{n-1} = 0 per
!!    mode with c = (omega dt)^2/2, has u^n = cos(n phi_dt) + beta sin(n phi_dt),
!!    cos(phi_dt) = 1/(1 + c), from its Taylor start u^{-1} = (1 - c) u^0 (beta =
!!    (cos(phi_dt) - 1 + c)/sin(phi_dt)); a rigid-body motion moves at constant velocity.
!!
!!    Tolerance: the eigenpair's residual (computed here: |K phi - omega^2 M phi| relative,
!!    1e-13 to 1e-11 measured) becomes a component in the other modes of the same relative
!!    size, which the rule keeps bounded; each step adds round-off of at most about
!!    eps cond(W), cond(W) <= 1 + (theta dt omega_max)^2 (W = M + theta^2 dt^2 K after
!!    diagonal scaling; omega_max from `highest_frequency`), so after n steps
!!    4 (residual + n eps cond(W)) of max |U|. The position scheme's W = M + theta dt^2 K
!!    has cond(W) <= 1 + theta (dt omega_max)^2, and its two-step recursion carries a
!!    perturbation of step k into step n as sin((n - k) phi_dt)/sin(phi_dt): the round-off
!!    term is divided by sin(phi_dt).
program test_support_dynamics
   use vibrobeam_kinds, only: dp
   use vibrobeam_scene, only: scene_type
   use vibrobeam_problem, only: run_problem, new_stepper
   use vibrobeam_time_stepper, only: time_stepper
   use vibrobeam_model, only: nodal_displacement, rigid_motions
   use vibrobeam_modes, only: compute_modes
   use vibrobeam_band, only: band_matvec
   use vibrobeam_highest_frequency, only: highest_frequency
   use vibrobeam_test_support, only: test_counter, prepare_test_scene
   implicit none
   type(test_counter) :: t
   real(dp), parameter :: length = 0.8_dp, ei = 40
   character(len=8), parameter :: bases(2) = [character(len=8) :: 'hermite', 'bspline']
   character(len=8), parameter :: schemes(2) = [character(len=8) :: 'velocity', 'position']
   integer :: b, s
   do b = 1, 2
      do s = 1, 2
         call free_motion(bases(b), schemes(s), 'free', 'free', 0.0_dp, 0.0_dp)
         call free_motion(bases(b), schemes(s), 'sliding', 'free', 0.0_dp, 0.0_dp)
         call free_motion(bases(b), schemes(s), 'pinned', 'pinned', 3*ei/length, 0.0_dp)
         call free_motion(bases(b), schemes(s), 'clamped', 'free', 0.0_dp, 20*ei/length**3)
      end do
   end do
   call t%finish('test_support_dynamics')

contains

   function beam_scene(basis, scheme, left, right) result(scene)
      character(len=*), intent(in) :: basis, scheme, left, right
      type(scene_type) :: scene
      scene%beam%length = length
      scene%beam%k2 = ei
      scene%beam%left_end = left
      scene%beam%right_end = right
      scene%mesh%basis = basis
      scene%mesh%elements = 16
      scene%time%scheme = scheme
      allocate (scene%obstacles(0))
   end function beam_scene

   !> Released in the first flexible mode with a rigid-body velocity: U_n against the
   !! exact discrete solution (module documentation).
   subroutine free_motion(basis, scheme, left, right, rotational_spring, tip_spring)
      character(len=*), intent(in) :: basis, scheme, left, right
      real(dp), intent(in) :: rotational_spring, tip_spring
      type(scene_type) :: scene
      type(run_problem) :: prepared
      class(time_stepper), allocatable :: stepper
      real(dp), allocatable :: omega(:), shapes(:,:), vectors(:,:), residual(:), mass_phi(:), exact(:)
      real(dp) :: a, omega_max, angle, condition, residual_size, tolerance, error, c, beta
      integer :: rigid, k, steps, stat, n
      character(len=512) :: errmsg
      character(len=:), allocatable :: label
      integer, parameter :: step_count = 400
      scene = beam_scene(basis, scheme, left, right)
      if (rotational_spring > 0) then
         scene%beam%left_rotational_spring = rotational_spring
         scene%beam%right_rotational_spring = rotational_spring
      end if
      if (tip_spring > 0) scene%beam%right_spring = tip_spring
      label = trim(basis)//' '//trim(scheme)//' '//left//'-'//right
      if (rotational_spring > 0 .or. tip_spring > 0) label = label//' with springs'
      call prepare_test_scene(scene, prepared)
      rigid = rigid_motions(prepared%model)
      call compute_modes(prepared%model, rigid + 1, omega, shapes, vectors, stat, errmsg)
      call t%check_true(label//': modes', stat == 0, trim(errmsg))
      if (stat /= 0) return
      call t%check_true(label//': '//achar(48 + rigid)//' rigid-body modes at omega = 0', .not. any(abs(omega(1:rigid)) > 0))
      ! the time step: omega dt = 0.3 for the flexible mode
      scene%time%dt = 0.3_dp/omega(rigid + 1)
      scene%time%t_end = step_count*scene%time%dt
      a = 1e-3_dp
      prepared%start%u = a*vectors(:, rigid + 1)
      prepared%start%v = 0
      do k = 1, rigid
         prepared%start%v = prepared%start%v + 1e-2_dp*k*vectors(:, k)
      end do
      call new_stepper(scene, prepared, stepper, stat, errmsg)
      call t%check_true(label//': stepper', stat == 0, trim(errmsg))
      if (stat /= 0) return
      do n = 1, step_count
         call stepper%step(stat, errmsg)
         if (stat /= 0) exit
      end do
      call t%check_true(label//': steps', stat == 0, trim(errmsg))
      steps = step_count
      allocate (exact(prepared%model%unknowns))
      if (scheme == 'velocity') then
         angle = 2*atan(omega(rigid + 1)*scene%time%dt/2)
         exact = a*cos(steps*angle)*vectors(:, rigid + 1) + steps*scene%time%dt*prepared%start%v
      else
         c = (omega(rigid + 1)*scene%time%dt)**2/2
         angle = acos(1/(1 + c))
         beta = (cos(angle) - 1 + c)/sin(angle)
         exact = a*(cos(steps*angle) + beta*sin(steps*angle))*vectors(:, rigid + 1) + &
                 steps*scene%time%dt*prepared%start%v
      end if
      ! the eigenpair's relative residual |K phi - omega^2 M phi| / |K phi|
      allocate (residual(prepared%model%unknowns), mass_phi(prepared%model%unknowns))
      call band_matvec(prepared%model%stiffness, vectors(:, rigid + 1), residual)
      call band_matvec(prepared%model%mass, vectors(:, rigid + 1), mass_phi)
      residual_size = maxval(abs(residual - omega(rigid + 1)**2*mass_phi))/maxval(abs(residual))
      call highest_frequency(prepared%model, omega_max, stat, errmsg)
      if (scheme == 'velocity') then
         condition = 1 + (0.5_dp*scene%time%dt*omega_max)**2
      else
         condition = (1 + 0.5_dp*(scene%time%dt*omega_max)**2)/sin(angle)
      end if
      tolerance = 4*(residual_size + steps*epsilon(1.0_dp)*condition)
      error = maxval(abs(stepper%u - exact))/maxval(abs(exact))
      write (*, '(a,es10.3,a,es10.3,a,es10.3)') label//': relative error of U_n ', error, ', eigen residual ', &
         residual_size, ', tolerance ', tolerance
      call t%check_close(label//': U after the steps against the exact discrete solution', error, 0.0_dp, 1.0_dp, &
                         tolerance)
   end subroutine free_motion
end program test_support_dynamics
