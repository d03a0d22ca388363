!> Verification driver for the SDNL104 case with a rigid stop (verification/published):
!!   check_sdnl104 DYNAMICS.h5 STATIC.h5 DYNAMICS.nml STATIC.nml
!! 1. First contact: the beam starts at rest under a constant tip force F; until contact
!!    u_tip(t) = sum_k 4F/(rho S L omega_k^2) (1 - cos(omega_k t)) (closed-form cantilever
!!    modes with tip value 1, whose squared norm is L/4; 60 modes, the series' terms fall
!!    like k^-4), which reaches -g at t_c, found here by bisection. The first impact of the
!!    run must lie within 2 dt of t_c; the derived value quoted with the case is 0.03615 s.
!! 2. Energy: no dissipation with e = 1 and theta = 1/2: the balance total - work stays
!!    constant to its round-off bound (`vibrobeam_roundoff_bounds`, the run repeated step
!!    by step: evaluation of the energies, every step's rounding, the impacts'
!!    complementarity).
!! 3. Static: /static/reaction = |F| - 3 EI g/L^3 (exact for Hermite elements) to its
!!    derived round-off bound (`static_report`'s reaction_bound, the static solve repeated
!!    here), plus the rounding of the closed form (gamma_8 (|F| + 3 EI g/L^3)).
program check_sdnl104
   use vibrobeam_kinds, only: dp, output_unit, pi
   use vibrobeam_hdf5_file_reads, only: read_real_1d
   use vibrobeam_cantilever_exact, only: cantilever_root
   use vibrobeam_scene, only: scene_type
   use vibrobeam_problem, only: run_problem
   use vibrobeam_roundoff_bounds, only: balance_bounds_at, gamma_n
   use vibrobeam_static, only: solve_static, static_report
   use vibrobeam_test_support, only: test_counter, read_test_scene, prepare_test_scene
   implicit none
   real(dp), parameter :: length = 1, radius = 0.1_dp, young = 1e10_dp, density = 1e6_dp
   real(dp), parameter :: force = -1000, gap = 1e-4_dp, dt = 1e-4_dp
   integer, parameter :: modes = 60
   type(test_counter) :: t
   character(len=512) :: dynamics_file, static_file, dynamics_input, static_input, errmsg
   real(dp), allocatable :: impact_time(:), kinetic(:), elastic(:), work(:), reaction(:), time(:), bounds(:), &
                            u_static(:), r_static(:)
   integer :: iterations
   type(static_report) :: static_accuracy
   real(dp) :: area, inertia, rho_s, ei, omega(modes), low, high, middle, exact_reaction, drift, ratio
   integer :: stat, k, iteration
   type(scene_type) :: scene
   type(run_problem) :: prepared
   call get_command_argument(1, dynamics_file)
   call get_command_argument(2, static_file)
   call get_command_argument(3, dynamics_input)
   call get_command_argument(4, static_input)
   area = pi*radius**2
   inertia = pi*radius**4/4
   rho_s = density*area
   ei = young*inertia
   omega = [(cantilever_root(k)**2*sqrt(ei/rho_s)/length**2, k=1, modes)]
   write (output_unit, '(a,f10.5,a)') 'omega_1 = ', omega(1), ' rad/s (5 (beta_1 L)^2)'
   ! 1. first contact
   low = 0
   high = 0.06_dp
   do iteration = 1, 200
      middle = 0.5_dp*(low + high)
      if (tip(middle) > -gap) then
         low = middle
      else
         high = middle
      end if
   end do
   call read_real_1d(trim(dynamics_file), '/impacts/time', impact_time, stat, errmsg)
   call t%check_true('read /impacts/time', stat == 0 .and. size(impact_time) > 0, errmsg)
   if (t%failed > 0) call t%finish('check_sdnl104')
   write (output_unit, '(a,f12.8,a,f12.8,a)') 'first contact: closed-form modal series ', middle, &
      ' s, vibrobeam ', impact_time(1), ' s'
   call t%check_close('first impact time (s), |error| within 2 dt', abs(impact_time(1) - middle), 0.0_dp, 1.0_dp, 2*dt)
   ! 2. energy
   call read_real_1d(trim(dynamics_file), '/time', time, stat, errmsg)
   if (stat == 0) call read_real_1d(trim(dynamics_file), '/energy/kinetic', kinetic, stat, errmsg)
   if (stat == 0) call read_real_1d(trim(dynamics_file), '/energy/elastic', elastic, stat, errmsg)
   if (stat == 0) call read_real_1d(trim(dynamics_file), '/energy/work', work, stat, errmsg)
   call t%check_true('read the energies', stat == 0, errmsg)
   drift = maxval(abs(kinetic + elastic - work))/maxval(abs(work))
   write (output_unit, '(a,es10.3,a,f10.6,a)') 'max |E - W|/max|W| = ', drift, ', kinetic energy at 0.16 s ', &
      kinetic(size(kinetic)), ' J'
   bounds = balance_bounds_at(trim(dynamics_input), time)
   ratio = 0
   do k = 2, size(time)
      ratio = max(ratio, abs(kinetic(k) + elastic(k) - work(k) - (kinetic(1) + elastic(1) - work(1)))/bounds(k))
   end do
   write (output_unit, '(a,es10.3,a,es10.3,a)') 'largest |E - W - (E0 - W0)| / round-off bound ', ratio, &
      ' (the bound at the end is ', bounds(size(bounds))/maxval(abs(work)), ' of max|W|)'
   call t%check_close('energy balance with e = 1 / its round-off bound', ratio, 0.0_dp, 1.0_dp, 1.0_dp)
   ! 3. static reaction
   call read_real_1d(trim(static_file), '/static/reaction', reaction, stat, errmsg)
   call t%check_true('read /static/reaction', stat == 0 .and. size(reaction) == 1, errmsg)
   if (t%failed > 0) call t%finish('check_sdnl104')
   exact_reaction = abs(force) - 3*ei*gap/length**3
   write (output_unit, '(a,f12.6,a,f12.6,a)') 'static reaction: vibrobeam ', reaction(1), ' N, beam theory ', &
      exact_reaction, ' N'
   scene = read_test_scene(trim(static_input))
   call prepare_test_scene(scene, prepared)
   allocate (u_static(prepared%model%unknowns), r_static(prepared%contacts%count))
   call solve_static(prepared%model, prepared%contacts, prepared%loads%at(0.0_dp), u_static, r_static, iterations, &
                     stat, errmsg, report=static_accuracy)
   call t%check_true('repeat the static solve for its round-off bound', stat == 0, errmsg)
   if (t%failed > 0) call t%finish('check_sdnl104')
   call t%check_close('static reaction on the rigid stop (N), |error| within its round-off bound', &
                      abs(reaction(1) - exact_reaction), 0.0_dp, 1.0_dp, &
                      static_accuracy%reaction_bound(1) + gamma_n(8)*(abs(force) + 3*ei*gap/length**3))
   call t%finish('check_sdnl104')
contains
   !> Tip displacement of the beam at rest loaded by F at the tip from t = 0 (no contact).
   pure function tip(time) result(u)
      real(dp), intent(in) :: time
      real(dp) :: u
      u = sum(4*force/(rho_s*length*omega**2)*(1 - cos(omega*time)))
   end function tip
end program check_sdnl104
