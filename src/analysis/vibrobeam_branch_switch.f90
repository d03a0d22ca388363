!> Branch switching at a period doubling (&periodic switch_branch; docs/method.md,
!! "Branch switching at a period doubling"): at the first located period doubling of a
!! continued branch of orbits of k forcing periods, the branch of orbits of 2k periods
!! that is born there, found and continued in the same parameter.
!!
!! Beyond the doubling the orbit x1 of k periods has a real multiplier below -1, with
!! eigenvector w; the orbit of 2k periods meets it at the doubling, its two phases at
!! x1 +- c w + ..., so at x1 the 2k-period map has a pitchfork. From the first branch point
!! beyond the doubling, Newton's method on the 2k-period map starts at x1 + c ||x1|| w
!! (energy norm, w of unit norm), c = first_move, doubled while Newton's method returns to
!! an orbit of k periods (`half_period_test` not positive: it is fixed by the k-period map
!! too) up to largest_move. The orbit of 2k periods found is then continued both ways
!! (`continue_branch`, period_multiple 2k, the same bounds): towards the doubling and
!! away from it, each part until the branch point where the orbit becomes one of k periods
!! again (kind 5) or a bound; the part towards the doubling, reversed, comes first.
module vibrobeam_branch_switch
   use vibrobeam_kinds, only: dp, int64
   use vibrobeam_status, only: outcome_ok, outcome_failed, outcome_interrupted
   use vibrobeam_text, only: real_text, integer_text
   use vibrobeam_scene, only: scene_type, forcing_period_steps
   use vibrobeam_problem, only: run_problem
   use vibrobeam_period_map, only: map_image, jacobian_none
   use vibrobeam_periodic_analysis, only: find_periodic_orbit, periodic_orbit
   use vibrobeam_continuation, only: continuation_branch, continue_branch
   use vibrobeam_continuation_map, only: scene_at_parameter
   use vibrobeam_branch_point, only: kind_doubling, half_period_test
   use vibrobeam_lapack, only: dgeev
   implicit none
   private
   public :: switched_branch, switch_branch

   !> The first move along w, relative to ||x1||, and the largest tried (doubling from the
   !! first): Newton's method returns to x1 from closer than about 1/sqrt(3) of the phases'
   !! distance (the pitchfork's normal form) and overshoots to one phase from far beyond it;
   !! measured at 181 rad/s on verification/periodic/period_doubling.nml, the phases lie
   !! 6.2e-2 ||x1|| from x1: 0.03 returns, 0.05 and 0.1 reach them, 0.2 reaches one of them.
   real(dp), parameter :: first_move = 0.01_dp, largest_move = 0.64_dp

   !> The branch of twice the period and where it came from.
   type :: switched_branch
      type(continuation_branch) :: branch         !! its points in parameter order from the doubling's end
      logical :: switched = .false.               !! a start was looked for (else `note` says why not)
      character(len=512) :: note = ''
      integer :: period_multiple = 0              !! 2k
      real(dp) :: doubling = 0                    !! lambda of the located period doubling it switched at
      real(dp) :: start = 0                       !! lambda of the switch: the first branch point beyond it
      real(dp) :: move = 0                        !! c, the move along w that reached the orbit of 2k periods
      integer :: towards_points = 0               !! points of the part continued towards the doubling
   end type switched_branch

contains

   !> The branch of 2k periods from the first located period doubling of `first` (the
   !! branch of `scene`, a continuation of k = period_multiple periods). stat /= 0
   !! (errmsg): a problem or stepper cannot be made; a switch that finds no orbit of 2k
   !! periods, or whose continuation ends early, is second%branch%status = outcome_failed
   !! with the reason; no doubling to switch at is second%switched = .false. with a note.
   subroutine switch_branch(scene, first, second, stat, errmsg)
      type(scene_type), intent(in) :: scene
      type(continuation_branch), intent(in) :: first
      type(switched_branch), intent(out) :: second
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      type(scene_type) :: local, double
      type(run_problem) :: prepared
      type(periodic_orbit) :: one, two
      type(continuation_branch) :: towards, away
      type(map_image) :: image
      real(dp), allocatable :: w(:)
      real(dp) :: size_of_x1
      integer(int64) :: steps
      integer :: which, beyond
      stat = 0
      errmsg = ''
      which = 0
      if (size(first%bifurcations) > 0) &
         which = findloc(first%bifurcations%kind == kind_doubling .and. first%bifurcations%located, .true., dim=1)
      if (which == 0) then
         second%note = 'no period doubling was located on the branch: there is no branch of twice the period to '// &
                       'switch to'
         return
      end if
      second%doubling = first%bifurcations(which)%parameter
      beyond = first%bifurcations(which)%index + 1
      if (beyond > size(first%points)) then
         second%note = 'the period doubling at '//trim(first%axis%parameter)//' = '//real_text(second%doubling)// &
                       ' lies beyond the last point kept (at a bound or max_points): no orbit beyond it to switch from'
         return
      end if
      second%switched = .true.
      second%start = first%points(beyond)%parameter
      second%period_multiple = 2*scene%periodic%period_multiple
      second%branch%axis = first%axis
      allocate (second%branch%points(0), second%branch%bifurcations(0))
      call scene_at_parameter(scene, first%axis, forcing_period_steps(scene), second%start, local, prepared, stat, errmsg)
      if (stat /= 0) return
      local%periodic%steps_per_period = int(forcing_period_steps(scene))
      local%initial%from_file = ''
      ! x1 again with its monodromy (the corrector's tolerance is met: no iteration), and w
      call find_periodic_orbit(local, prepared, one, stat, errmsg, start=first%points(beyond)%x)
      if (stat /= 0) return
      steps = one%map%steps_taken
      if (one%converged) call doubling_vector(one%image%jacobian, w)
      if (.not. allocated(w)) then
         call give_up('the orbit there has no real Floquet multiplier below -1 '//trim(one%failure))
         return
      end if
      w = w/one%map%norm(prepared, w)
      size_of_x1 = one%map%norm(prepared, one%x)
      double = local
      double%periodic%period_multiple = second%period_multiple
      second%move = first_move
      do while (second%move <= largest_move)
         call find_periodic_orbit(double, prepared, two, stat, errmsg, start=one%x + second%move*size_of_x1*w)
         if (stat /= 0) return
         steps = steps + two%map%steps_taken
         if (two%status == outcome_interrupted) then
            second%branch%status = outcome_interrupted
            second%branch%steps_taken = steps
            return
         end if
         if (two%converged) then
            call one%map%evaluate(local, prepared, two%x, jacobian_none, image, stat, errmsg)
            if (stat /= 0) return
            steps = steps + one%map%steps
            if (image%status == outcome_ok) then
               if (half_period_test(one%map%norm(prepared, image%state - two%x), &
                                    max(one%map%norm(prepared, two%x), one%map%norm(prepared, image%state)), &
                                    .true., scene%periodic%tolerance) > 0) exit
            end if
         end if
         second%move = 2*second%move
      end do
      if (second%move > largest_move) then
         call give_up('Newton''s method on the map of '//integer_text(second%period_multiple)// &
                      ' periods from x1 + c ||x1|| w, c = '//real_text(first_move)//' doubled up to '// &
                      real_text(largest_move)//', reached no orbit that the map of '// &
                      integer_text(scene%periodic%period_multiple)//' periods does not fix')
         return
      end if
      ! the two parts: towards the doubling, then away from it with the points left
      double%periodic%step = sign(abs(scene%periodic%step), second%doubling - second%start)
      call continue_branch(double, prepared, towards, stat, errmsg, start_state=two%x)
      if (stat /= 0) return
      double%periodic%step = -double%periodic%step
      double%periodic%max_points = max(2, scene%periodic%max_points - size(towards%points) + 1)
      call continue_branch(double, prepared, away, stat, errmsg, start_state=two%x)
      if (stat /= 0) return
      call join(towards, away, second%branch)
      second%towards_points = size(towards%points)
      second%branch%steps_taken = second%branch%steps_taken + steps
   contains
      !> The switch ends without an orbit of 2k periods: failed, with the reason.
      subroutine give_up(reason)
         character(len=*), intent(in) :: reason
         second%branch%status = outcome_failed
         second%branch%failure = 'the switch at '//trim(first%axis%parameter)//' = '//real_text(second%start)// &
                                 ' (beyond the period doubling at '//real_text(second%doubling)//'): '//trim(reason)
         second%branch%steps_taken = steps
      end subroutine give_up
   end subroutine switch_branch

   !> The real eigenvector of `monodromy` whose eigenvalue is the lowest below -1 (LAPACK
   !! dgeev's right vectors); unallocated when no real eigenvalue lies below -1.
   subroutine doubling_vector(monodromy, w)
      real(dp), intent(in) :: monodromy(:, :)
      real(dp), allocatable, intent(out) :: w(:)
      real(dp), allocatable :: a(:, :), wr(:), wi(:), vr(:, :), work(:)
      real(dp) :: unused(1, 1), query(1)
      integer :: n, info, i, pick
      n = size(monodromy, 1)
      allocate (a(n, n), wr(n), wi(n), vr(n, n))
      a(:, :) = monodromy
      call dgeev('N', 'V', n, a, n, wr, wi, unused, 1, vr, n, query, -1, info)
      allocate (work(max(1, int(query(1)))))
      call dgeev('N', 'V', n, a, n, wr, wi, unused, 1, vr, n, work, size(work), info)
      if (info /= 0) return
      pick = 0
      do i = 1, n
         if (abs(wi(i)) > 0 .or. .not. wr(i) < -1) cycle
         if (pick == 0) then
            pick = i
         else if (wr(i) < wr(pick)) then
            pick = i
         end if
      end do
      if (pick > 0) w = vr(:, pick)
   end subroutine doubling_vector

   !> One branch of the two parts continued from the same orbit: `towards` reversed (its
   !! first point, the shared start, last), then `away` without its first point; each
   !! bifurcation's `index` renumbered to the point before it in that order (0: before the
   !! first point, the end towards the doubling). Cost, status and failure of both.
   subroutine join(towards, away, joined)
      type(continuation_branch), intent(in) :: towards, away
      type(continuation_branch), intent(inout) :: joined
      integer :: n, j
      n = size(towards%points)
      joined%points = [towards%points(n:1:-1), away%points(2:)]
      joined%bifurcations = [towards%bifurcations(size(towards%bifurcations):1:-1), away%bifurcations]
      do j = 1, size(towards%bifurcations)
         joined%bifurcations(j)%index = n - joined%bifurcations(j)%index
      end do
      do j = size(towards%bifurcations) + 1, size(joined%bifurcations)
         joined%bifurcations(j)%index = joined%bifurcations(j)%index + n - 1
      end do
      joined%monodromy = away%monodromy
      joined%orbit_steps = away%orbit_steps
      joined%first_iterations = towards%first_iterations
      joined%steps_taken = towards%steps_taken + away%steps_taken
      joined%status = outcome_ok
      if (towards%status /= outcome_ok) joined%status = towards%status
      if (away%status /= outcome_ok) joined%status = away%status
      joined%failure = towards%failure
      if (len_trim(joined%failure) == 0) joined%failure = away%failure
   end subroutine join
end module vibrobeam_branch_switch
