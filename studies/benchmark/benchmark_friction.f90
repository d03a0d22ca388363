!> Benchmark of the 2-D frictional contact solver (issue 21; FRICTION_REPORT.md), a study,
!! not a test: it asserts nothing and is not run by ctest; benchmark_friction.sh builds it
!! in Release, runs it and writes benchmark_friction.txt beside this file.
!!
!! For m = 1, 2, 5, 10, 20, 50 contacts, on `problems_per_size` random problems each,
!! median wall time of one solve (median of `samples` samples, each the mean of enough
!! repeats to last `sample_seconds`):
!! * friction: `solve_frictional_contact` with mu in [0.2, 1] on problems where every
!!   contact is closed, half of them sticking and half slipping (the hard case: every
!!   contact enters the basis and most of them change state from the start, q built from
!!   that solution as in the unit test);
!! * mu = 0: the same solver with mu = 0 on the same D and q (Lemke on D_NN);
!! * baseline: `solve_lcp` (block principal pivoting, the frictionless solver of today's
!!   steps) on the same mu = 0 problem, LCP(D_NN, q_N), measured in the same run.
!! D = B^T B + 0.2 I (2m x 2m), B uniform in (-1, 1)/sqrt(2m).
!!
!! Usage: benchmark_friction [TABLE_FILE] ['quick']
program benchmark_friction
   use vibrobeam_kinds, only: dp, int64, output_unit, error_unit
   use vibrobeam_sorting, only: median
   use vibrobeam_frictional_contact, only: solve_frictional_contact, frictional_contact_solution
   use vibrobeam_lcp, only: solve_lcp
   use vibrobeam_test_support, only: use_program_blas_threads
   implicit none

   integer, parameter :: sizes(*) = [1, 2, 5, 10, 20, 50]
   integer :: problems_per_size = 5, samples = 11
   real(dp) :: sample_seconds = 0.02_dp
   character(len=4096) :: table_path, mode
   integer :: table_unit, size_index, m, problem, i
   real(dp), allocatable :: d(:, :), q(:), mu(:), zeros(:)
   real(dp) :: t_friction(5), t_frictionless(5), t_baseline(5)
   integer :: pivots(5), pivots_frictionless(5)
   character(len=160) :: line

   call use_program_blas_threads()   ! one BLAS thread, as the program runs (dgesv on n <= 200)
   call get_command_argument(1, table_path)
   call get_command_argument(2, mode)
   if (trim(mode) == 'quick') then
      problems_per_size = 1
      samples = 3
      sample_seconds = 0.001_dp
   end if
   call random_init(repeatable=.true., image_distinct=.true.)
   if (len_trim(table_path) > 0) then
      open (newunit=table_unit, file=trim(table_path), status='replace', action='write')
   else
      table_unit = output_unit
   end if
   write (table_unit, '(a)') '# benchmark_friction: one frictional contact solve (2-D Coulomb, Lemke on Stewart & '// &
      'Trinkle''s LCP) against the frictionless solve_lcp'
   write (table_unit, '(a, i0, a, i0, a, f6.3, a)') '# medians over ', problems_per_size, ' problems of the median of ', &
      samples, ' samples of >= ', sample_seconds, ' s each; every contact closed, half sticking, half slipping'
   write (table_unit, '(a)') '#  m  LCP  pivots  friction_us  pivots_mu0  lemke_mu0_us  solve_lcp_us' // &
      '  friction/solve_lcp  lemke_mu0/solve_lcp'
   do size_index = 1, size(sizes)
      m = sizes(size_index)
      do problem = 1, problems_per_size
         call closed_problem(m, d, q, mu)
         zeros = [(0.0_dp, i=1, m)]
         t_friction(problem) = time_friction(d, q, mu, pivots(problem))
         t_frictionless(problem) = time_friction(d, q, zeros, pivots_frictionless(problem))
         t_baseline(problem) = time_lcp(d(1:2*m:2, 1:2*m:2), q(1:2*m:2))
      end do
      associate (tf => median(t_friction(1:problems_per_size)), t0 => median(t_frictionless(1:problems_per_size)), &
                 tb => median(t_baseline(1:problems_per_size)))
         write (line, '(i4, i5, f8.1, f13.2, f12.1, f14.2, f14.2, f20.2, f21.2)') m, 4*m, &
            median(real(pivots(1:problems_per_size), dp)), 1e6_dp*tf, &
            median(real(pivots_frictionless(1:problems_per_size), dp)), 1e6_dp*t0, 1e6_dp*tb, tf/tb, t0/tb
      end associate
      write (table_unit, '(a)') trim(line)
      flush (table_unit)
   end do
   if (table_unit /= output_unit) close (table_unit)

contains

   !> D = B^T B + 0.2 I and q built from a solution in which every contact is closed,
   !! odd contacts sticking (|r_T| < mu p, u = 0) and even ones slipping (u_T /= 0).
   subroutine closed_problem(m, d, q, mu)
      integer, intent(in) :: m
      real(dp), allocatable, intent(out) :: d(:, :), q(:), mu(:)
      real(dp) :: b(2*m, 2*m), r(2*m), u(2*m), x(4)
      integer :: i
      call random_number(b)
      b = (2.0_dp*b - 1.0_dp)/sqrt(real(2*m, dp))
      allocate (d(2*m, 2*m), q(2*m), mu(m))
      d = matmul(transpose(b), b)
      do i = 1, 2*m
         d(i, i) = d(i, i) + 0.2_dp
      end do
      d = 0.5_dp*(d + transpose(d))
      u = 0.0_dp
      do i = 1, m
         call random_number(x)
         mu(i) = 0.2_dp + 0.8_dp*x(1)
         r(2*i - 1) = 0.1_dp + x(2)
         if (mod(i, 2) == 1) then
            r(2*i) = (2.0_dp*x(3) - 1.0_dp)*0.9_dp*mu(i)*r(2*i - 1)
         else
            u(2*i) = sign(0.1_dp + x(3), x(4) - 0.5_dp)
            r(2*i) = -mu(i)*r(2*i - 1)*sign(1.0_dp, u(2*i))
         end if
      end do
      q = u - matmul(d, r)
   end subroutine closed_problem

   !> Median seconds of one solve_frictional_contact; its pivots.
   real(dp) function time_friction(d, q, mu, pivots) result(seconds)
      real(dp), intent(in) :: d(:, :), q(:), mu(:)
      integer, intent(out) :: pivots
      type(frictional_contact_solution) :: solution
      real(dp) :: sample(samples)
      integer(int64) :: start, finish, rate
      integer :: repeats, k, s, stat
      character(len=512) :: errmsg
      call solve_frictional_contact(d, q, mu, solution, stat, errmsg)
      if (stat /= 0) write (error_unit, '(a)') 'benchmark_friction: '//trim(errmsg)
      pivots = solution%pivots
      repeats = calibrated_repeats(d, q, mu)
      do s = 1, samples
         call system_clock(start, rate)
         do k = 1, repeats
            call solve_frictional_contact(d, q, mu, solution, stat, errmsg)
         end do
         call system_clock(finish)
         sample(s) = real(finish - start, dp)/real(rate, dp)/repeats
      end do
      seconds = median(sample)
   end function time_friction

   !> Repeats of solve_frictional_contact that last about sample_seconds.
   integer function calibrated_repeats(d, q, mu) result(repeats)
      real(dp), intent(in) :: d(:, :), q(:), mu(:)
      type(frictional_contact_solution) :: solution
      integer(int64) :: start, finish, rate
      integer :: stat
      character(len=512) :: errmsg
      repeats = 1
      do
         call system_clock(start, rate)
         block
            integer :: k
            do k = 1, repeats
               call solve_frictional_contact(d, q, mu, solution, stat, errmsg)
            end do
         end block
         call system_clock(finish)
         if (real(finish - start, dp)/real(rate, dp) >= sample_seconds .or. repeats > 2**24) exit
         repeats = 2*repeats
      end do
   end function calibrated_repeats

   !> Median seconds of one solve_lcp(a, q) (the same sampling).
   real(dp) function time_lcp(a, q) result(seconds)
      real(dp), intent(in) :: a(:, :), q(:)
      real(dp) :: z(size(q)), w(size(q)), sample(samples)
      integer(int64) :: start, finish, rate
      integer :: repeats, k, s, stat, iterations
      character(len=512) :: errmsg
      repeats = 1
      do
         call system_clock(start, rate)
         do k = 1, repeats
            call solve_lcp(a, q, z, w, iterations, stat, errmsg)
         end do
         call system_clock(finish)
         if (real(finish - start, dp)/real(rate, dp) >= sample_seconds .or. repeats > 2**24) exit
         repeats = 2*repeats
      end do
      if (stat /= 0) write (error_unit, '(a)') 'benchmark_friction: '//trim(errmsg)
      do s = 1, samples
         call system_clock(start, rate)
         do k = 1, repeats
            call solve_lcp(a, q, z, w, iterations, stat, errmsg)
         end do
         call system_clock(finish)
         sample(s) = real(finish - start, dp)/real(rate, dp)/repeats
      end do
      seconds = median(sample)
   end function time_lcp

end program benchmark_friction
