!> Branch switching at a period doubling (issue 20, item 2; docs/method.md, "Continuation
!! of periodic orbits"): beyond the doubling of period_doubling.nml, the period-2 orbit is
!! found by Newton's method on the map of 2 forcing periods started from the period-1
!! orbit moved along the eigenvector of its multiplier below -1, the start a branch switch
!! takes, instead of from a transient of time marching.
!!
!! The scene (period_doubling_orbit.nml, 181 rad/s, period_multiple = 2) is solved three
!! ways: the period-1 orbit x1 (the same scene with period_multiple = 1, from the
!! transient: Newton's method converges to it although it is unstable); the period-2
!! orbit x2 from the transient (test_periodic_marching shows it equals the state time
!! marching settles to); and the period-2 orbit from x1 + s eps w and x1 - s eps w, w the
!! real eigenvector of x1's monodromy whose multiplier is below -1 (unit energy norm),
!! s = ||x1||, eps = 0.1. The period-2 orbit's two phases lie 6.2e-2 s from x1 (energy
!! norm, measured), on either side along w: at x1 the 2-period map has a pitchfork, and
!! Newton's method on it returns to x1 from a start closer than about 1/sqrt(3) of that
!! distance (the pitchfork's normal form) and overshoots to one phase from either side when
!! much farther. Measured: eps = 0.03 returns to x1 (6 checks fail), 0.05 and 0.1 reach
!! the two phases, 0.2 reaches one phase from both starts.
!! Checked:
!! - x1 is unstable through a real multiplier below -1 (the doubling is behind);
!! - from x1 itself (eps = 0) Newton's method on the 2-period map stays at x1 (a period-1
!!   orbit is a fixed point of the 2-period map too: hence the perturbation);
!! - from x1 +- s eps w it converges, to a stable orbit that is not of period 1
!!   (||Phi_1(x) - x|| > 1e-3 ||x||), the two starts to the orbit's two phases (apart
!!   by more than 1e-3 ||x||), one of which is x2 to ||(I - M)^-1|| (2 tolerance + 2 noise)
!!   relative (energy norm): two fixed points of the same map, each within the tolerance,
!!   noise = 8 eps P rho the round-off of one evaluation (test_periodic_linear).
!! Usage: test_branch_switching SCENE.nml (a period_multiple = 2 scene beyond a doubling).
program test_branch_switching
   use vibrobeam_kinds, only: dp
   use vibrobeam_status, only: outcome_ok
   use vibrobeam_scene, only: scene_type
   use vibrobeam_problem, only: run_problem
   use vibrobeam_periodic_analysis, only: find_periodic_orbit, periodic_orbit
   use vibrobeam_period_map, only: map_image, jacobian_none
   use vibrobeam_periodic_reference, only: energy_gram, energy_norm, cancellation, fixed_point_condition
   use vibrobeam_lapack, only: dgeev
   use vibrobeam_test_support, only: test_counter, read_test_scene, prepare_test_scene
   implicit none
   real(dp), parameter :: eps_start = 0.1_dp
   type(test_counter) :: t
   type(scene_type) :: scene, single
   type(run_problem) :: prepared
   type(periodic_orbit) :: one, two, stay, plus, minus
   type(map_image) :: image
   character(len=512) :: path, errmsg
   real(dp), allocatable :: gram(:, :), w(:), a(:, :), wr(:), wi(:), vr(:, :), work(:)
   real(dp) :: unused(1, 1), query(1), scale, noise, condition, bound, error_plus, error_minus, distance
   integer :: stat, n, info, i, pick

   call get_command_argument(1, path)
   scene = read_test_scene(trim(path))
   call prepare_test_scene(scene, prepared)
   single = scene
   single%periodic%period_multiple = 1

   ! ---- the period-1 orbit and the eigenvector of its multiplier below -1 ----
   call find_periodic_orbit(single, prepared, one, stat, errmsg)
   call t%check_true('the period-1 orbit is found', stat == 0 .and. one%converged, trim(errmsg)//trim(one%failure))
   if (.not. one%converged) call t%finish('test_branch_switching')
   n = size(one%x)
   allocate (a(n, n), wr(n), wi(n), vr(n, n), w(n))
   a = one%image%jacobian
   call dgeev('N', 'V', n, a, n, wr, wi, unused, 1, vr, n, query, -1, info)
   allocate (work(int(query(1))))
   call dgeev('N', 'V', n, a, n, wr, wi, unused, 1, vr, n, work, size(work), info)
   if (info /= 0) error stop 'dgeev'
   pick = 0
   do i = 1, n
      if (.not. abs(wi(i)) > 0 .and. wr(i) < -1) then   ! (a real multiplier)
         if (pick == 0) then
            pick = i
         else if (wr(i) < wr(pick)) then
            pick = i
         end if
      end if
   end do
   call t%check_true('the period-1 orbit has a real multiplier below -1', pick > 0)
   if (pick == 0) call t%finish('test_branch_switching')
   write (*, '(a,f9.6,a,i0,a)') 'period-1 orbit: multiplier ', wr(pick), ' (', one%iterations, ' Newton iterations)'
   gram = energy_gram(prepared, one%map%omega)
   w = vr(:, pick)/energy_norm(gram, vr(:, pick))
   scale = energy_norm(gram, one%x)

   ! ---- the period-2 orbit from the transient (the state time marching settles to) ----
   call find_periodic_orbit(scene, prepared, two, stat, errmsg)
   call t%check_true('the period-2 orbit is found from the transient', stat == 0 .and. two%converged, &
                     trim(errmsg)//trim(two%failure))
   if (.not. two%converged) call t%finish('test_branch_switching')
   noise = 8*epsilon(1.0_dp)*real(two%map%steps, dp)*cancellation(gram, two%x)
   condition = fixed_point_condition(gram, two%image%jacobian)
   bound = condition*(2*scene%periodic%tolerance + 2*noise)

   ! ---- from x1 itself: Newton's method stays on the period-1 orbit ----
   call find_periodic_orbit(scene, prepared, stay, stat, errmsg, start=one%x)
   distance = energy_norm(gram, stay%x - one%x)/scale
   write (*, '(a,es10.3)') 'from x1 itself, the 2-period Newton ends at x1 to ', distance
   call t%check_true('from x1 itself the 2-period map''s Newton''s method stays at x1 (within 1e-6)', &
                     stat == 0 .and. stay%converged .and. distance < 1e-6_dp)

   ! ---- from x1 moved along w, both ways: the period-2 orbit's two phases ----
   call find_periodic_orbit(scene, prepared, plus, stat, errmsg, start=one%x + eps_start*scale*w)
   call check_period_two(plus, '+')
   call find_periodic_orbit(scene, prepared, minus, stat, errmsg, start=one%x - eps_start*scale*w)
   call check_period_two(minus, '-')
   if (.not. (plus%converged .and. minus%converged)) call t%finish('test_branch_switching')
   distance = energy_norm(gram, plus%x - minus%x)/scale
   call t%check_true('the two starts reach the orbit''s two phases (apart by more than 1e-3)', distance > 1e-3_dp)
   error_plus = energy_norm(gram, plus%x - two%x)/scale
   error_minus = energy_norm(gram, minus%x - two%x)/scale
   write (*, '(a,es10.3,a,es10.3,a,es10.3,a,es10.3,a)') 'against the orbit from the transient: +w ', error_plus, &
      ', -w ', error_minus, ' (bound ', bound, '; phases apart ', distance, ')'
   call t%check_close('one of the switched orbits equals the orbit time marching settles to (energy norm, relative)', &
                      min(error_plus, error_minus), 0.0_dp, bound, scale=1.0_dp)
   call t%check_true('the bound is tight enough to tell orbits apart (< 1e-6)', bound < 1e-6_dp)
   call t%finish('test_branch_switching')

contains

   !> The switched start converged to a stable orbit that the 1-period map does not fix.
   subroutine check_period_two(orbit, sign)
      type(periodic_orbit), intent(in) :: orbit
      character(len=*), intent(in) :: sign
      real(dp) :: modulus, repeat
      call t%check_true('from x1 '//sign//' s eps w Newton''s method converges', stat == 0 .and. orbit%converged, &
                        trim(errmsg)//trim(orbit%failure))
      if (.not. orbit%converged) return
      modulus = hypot(orbit%multipliers(1, 1), orbit%multipliers(2, 1))
      call one%map%evaluate(single, prepared, orbit%x, jacobian_none, image, stat, errmsg)
      if (stat /= 0 .or. image%status /= outcome_ok) error stop 'map evaluation failed'
      repeat = energy_norm(gram, image%state - orbit%x)/energy_norm(gram, orbit%x)
      write (*, '(3a,i0,a,f9.6,a,es10.3)') 'from x1 ', sign, ' s eps w: ', orbit%iterations, &
         ' Newton iterations, largest multiplier modulus ', modulus, ', ||Phi_1(x) - x||/||x|| ', repeat
      call t%check_true('the switched orbit ('//sign//'w) is stable', modulus < 1)
      call t%check_true('the switched orbit ('//sign//'w) is not of period 1 (||Phi_1(x) - x|| > 1e-3 ||x||)', &
                        repeat > 1e-3_dp)
   end subroutine check_period_two
end program test_branch_switching
