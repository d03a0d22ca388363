!> Static equilibrium against the obstacles of every structure but the uniform clamped-free
!! beam (other end supports, end springs; docs/method.md, "Statics"; theory §5 "Statics"),
!! where the double integration from the clamp of `vibrobeam_static` does not apply:
!!
!!     U = argmin 1/2 U^T K U - F^T U   subject to the obstacles at the contact points,
!!
!! solved in the reactions. Each contact side is a row r: a rigid bound (direction s_r = +1
!! below, -1 above, level t_r) or a linear compliant stop (force k (t_r - u) s_r while
!! positive, compliance 1/k). With G = H K^-1 H^T, the coupling of the m contact points
!! (m solves with the band Cholesky of K), the row forces z >= 0 solve the linear
!! complementarity problem
!!
!!     w = S G S z + diag(compliance) z + S (H K^-1 F - t) >= 0,   z >= 0,   z w = 0
!!
!! (w the gaps, S the directions; `vibrobeam_lcp`), the reaction of point c is the sum of
!! s_r z_r over its rows and U = K^-1 (F + H^T P). Cost: m + 2 band solves and a dense
!! m x m problem: at most `max_points` contact points.
!!
!! Accuracy: the band Cholesky of K (LAPACK dpbtrf) is backward stable; its forward error
!! grows like eps cond(K) ~ eps N^4 (docs/method.md). The final solve U = K^-1 (F + H^T P)
!! is refined by LAPACK dpbrfs, whose bound FERR of the relative error (max norm) covers
!! componentwise perturbations of K of (kd + 2) eps (Arioli, Demmel & Duff 1989; Higham,
!! Accuracy and Stability of Numerical Algorithms, 2002, §12.1); the assembled K carries up
!! to about 16 roundings per entry (four elements of a 4-point rule), so the bound published
!! is `ferr_factor` = 4 times FERR. Everything is solved in the scaled unknowns Y = D^-1 U,
!! D = diag(K)^-1/2 (K_s = D K D has a unit diagonal), so that FERR max|Y| D_i bounds each
!! unknown in its own units (a Hermite rotation and a deflection differ by a factor of
!! about h; a max-norm bound of the unscaled U would mix them). An answer whose position
!! bound exceeds `trusted` = 1e-6 of its scale is refused (stat_residual_check_failed): K
!! is too ill-conditioned at that N (the bound is guaranteed, measured 10 to 1000 times
!! above the actual error; it reaches 1e-6 near N = 100 to 300 Hermite elements for the
!! softest pairs, verification/statics/test_static_supports.f90). The reactions err by the positions' bound times the stiffness
!! of the coupling at their point, 1/G_cc.
!! Compliant stops must be linear (exponent 1) here; the validation of the scene says so.
!! A structure with a rigid-body motion has a singular K and is refused by the scene's
!! validation before it gets here (stat_numerical_failure if it does).
module vibrobeam_static_band
   use vibrobeam_kinds, only: dp
   use vibrobeam_status, only: stat_numerical_failure, stat_residual_check_failed, stat_invalid_argument
   use vibrobeam_model, only: beam_model, nodal_displacement, node_row
   use vibrobeam_lapack, only: dpbtrf, dpbtrs, dpbrfs
   use vibrobeam_contact_set, only: contact_set, contact_value, no_bound
   use vibrobeam_contact_system, only: scatter_rows
   use vibrobeam_lcp, only: solve_lcp
   use vibrobeam_static_report, only: static_report
   implicit none
   private
   public :: solve_static_band, max_points

   !> Most contact points the dense coupling G may hold (4096: 128 MB).
   integer, parameter :: max_points = 4096
   !> FERR of dpbrfs times this bounds the error of the assembled K's solution (module documentation).
   real(dp), parameter :: ferr_factor = 4
   !> The largest relative bound of the displacements accepted (six significant digits).
   real(dp), parameter :: trusted = 1e-6_dp

contains

   !> The equilibrium of `model` under `force` against the obstacles of `contacts` (module
   !! documentation). The arguments are those of `solve_static`; stat: 0,
   !! stat_numerical_failure (K not positive definite), stat_invalid_argument (too many
   !! contact points, a compliant stop that is not linear), the LCP solver's codes, or
   !! stat_residual_check_failed (the answer fails its check).
   subroutine solve_static_band(model, contacts, force, u, reaction, iterations, stat, errmsg, max_iterations, report)
      type(beam_model), intent(in) :: model
      type(contact_set), intent(in) :: contacts
      real(dp), intent(in) :: force(:)        !! F (J)
      real(dp), intent(out) :: u(:)           !! equilibrium (J)
      real(dp), intent(out) :: reaction(:)    !! (contacts%count) P_c, 0 if not in contact
      integer, intent(out) :: iterations, stat
      character(len=*), intent(out) :: errmsg
      integer, intent(in), optional :: max_iterations
      type(static_report), intent(out), optional :: report
      type(static_report) :: done
      real(dp), allocatable :: coupling(:,:), column(:), free(:), a(:,:), q(:), z(:), w(:), direction(:), &
                               level_of_row(:), compliance(:), scaled(:,:), factor(:,:), d(:), y(:), rhs(:), &
                               work(:), w_nodes(:)
      integer, allocatable :: point(:), iwork(:)
      integer :: m, rows, c, r, j, limit, n, kd, info, k
      real(dp) :: ferr(1), berr(1), scale
      iterations = 0
      stat = 0
      errmsg = ''
      u = 0
      reaction = 0
      m = contacts%count
      if (m > max_points) then
         stat = stat_invalid_argument
         write (errmsg, '(a,i0,a,i0,a)') 'the static solve of a '//model%boundary%name()//' beam couples its ', m, &
            ' contact points in a dense matrix: at most ', max_points, '; use fewer elements under the obstacles'
         return
      end if
      if (contacts%springs%count > 0) then
         if (any(abs(contacts%springs%exponent - 1) > 0)) stat = stat_invalid_argument
      end if
      if (stat == stat_invalid_argument) then
         stat = stat_invalid_argument
         errmsg = 'the static solve of a '//model%boundary%name()//' beam takes linear compliant stops only '// &
                  '(&obstacles exponent = 1)'
         return
      end if
      n = model%unknowns
      kd = model%stiffness%kd
      ! K_s = D K D, D = diag(K)^-1/2: U = D Y (module documentation)
      d = 1/sqrt(max(model%stiffness%lower(1, :), tiny(1.0_dp)))
      allocate (scaled, source=model%stiffness%lower)
      do j = 1, n
         do k = 1, min(kd + 1, n - j + 1)
            scaled(k, j) = scaled(k, j)*d(j)*d(j + k - 1)
         end do
      end do
      allocate (factor, source=scaled)
      call dpbtrf('L', n, kd, factor, kd + 1, info)
      if (info /= 0) then
         stat = stat_numerical_failure
         write (errmsg, '(a,i0,a)') 'the stiffness K of the '//model%boundary%name()//' beam is not positive '// &
            'definite (dpbtrf: leading minor ', info, '): a rigid-body motion that no support holds'
         return
      end if
      ! the rows: every finite bound and every spring of each point
      rows = count(contacts%lower > -no_bound) + count(contacts%upper < no_bound) + contacts%springs%count
      allocate (point(rows), direction(rows), level_of_row(rows), compliance(rows))
      r = 0
      do c = 1, m
         if (contacts%lower(c) > -no_bound) call add_row(c, 1.0_dp, contacts%lower(c), 0.0_dp)
         if (contacts%upper(c) < no_bound) call add_row(c, -1.0_dp, contacts%upper(c), 0.0_dp)
      end do
      do j = 1, contacts%springs%count
         call add_row(contacts%springs%point(j), contacts%springs%sign(j), contacts%springs%level(j), &
                      1/contacts%springs%stiffness(j))
      end do
      ! G = H K^-1 H^T, one solve per point, and the free equilibrium K^-1 F
      allocate (coupling(m, m), column(model%unknowns))
      do c = 1, m
         column = 0
         call scatter_rows(contacts, [c], [1.0_dp], column)
         call solve(column)
         do j = 1, m
            coupling(j, c) = contact_value(contacts, j, column)
         end do
      end do
      free = force
      call solve(free)
      allocate (a(rows, rows), q(rows), z(rows), w(rows))
      do r = 1, rows
         q(r) = direction(r)*(contact_value(contacts, point(r), free) - level_of_row(r))
         do j = 1, rows
            a(r, j) = direction(r)*direction(j)*0.5_dp*(coupling(point(r), point(j)) + coupling(point(j), point(r)))
         end do
         a(r, r) = a(r, r) + compliance(r)
      end do
      limit = max(100, rows**2)
      if (present(max_iterations)) then
         if (max_iterations > 0) limit = max_iterations
      end if
      call solve_lcp(a, q, z, w, iterations, stat, errmsg, max_iterations=limit)
      if (stat /= 0) then
         errmsg = 'static contact: '//trim(errmsg)
         return
      end if
      do r = 1, rows
         reaction(point(r)) = reaction(point(r)) + direction(r)*z(r)
      end do
      rhs = force
      call scatter_rows(contacts, [(c, c=1, m)], reaction, rhs)
      rhs = d*rhs
      y = rhs
      call dpbtrs('L', n, kd, 1, factor, kd + 1, y, n, info)
      ! refined by dpbrfs, with its bound (module documentation)
      allocate (work(3*n), iwork(n))
      call dpbrfs('L', n, kd, 1, scaled, kd + 1, factor, kd + 1, rhs, n, y, n, ferr, berr, work, iwork, info)
      u = d*y
      scale = maxval(abs(y))
      w_nodes = nodal_displacement(model, u)
      done%iterations = iterations
      done%levels = 1
      done%unknown_bound = ferr_factor*ferr(1)*scale*d
      done%position_bound = maxval(nodal_magnitude(done%unknown_bound))
      done%error_estimate = done%position_bound
      done%displacement_scale = maxval(abs(w_nodes))
      done%error_bound = trusted*maxval(nodal_magnitude(scale*d))
      ! each reaction's error: that of the positions times the coupling's stiffness at the point
      allocate (done%reaction_bound(m))
      do c = 1, m
         done%reaction_bound(c) = done%position_bound/max(coupling(c, c), tiny(1.0_dp))
      end do
      done%reaction_sum_bound = sum(done%reaction_bound)
      if (present(report)) report = done
      if (done%position_bound > done%error_bound .or. info /= 0) then
         stat = stat_residual_check_failed
         write (errmsg, '(a,es10.3,a,es10.3,a)') 'the static answer fails its check: its error bound ', &
            done%position_bound, ' m exceeds 1e-6 of the displacement scale ', done%error_bound/trusted, &
            ': K is too ill-conditioned at this N; use fewer elements'
      end if

   contains

      !> x := K^-1 x = D K_s^-1 D x with dpbtrf's factor of K_s.
      subroutine solve(x)
         real(dp), intent(inout) :: x(:)
         integer :: status
         x = d*x
         call dpbtrs('L', n, kd, 1, factor, kd + 1, x, n, status)
         x = d*x
      end subroutine solve

      !> |H_i| v at the nodes: the bound at each node of a field whose unknowns err by v >= 0.
      function nodal_magnitude(v) result(bound)
         real(dp), intent(in) :: v(:)
         real(dp) :: bound(model%elements + 1)
         integer :: i, a, dofs(4)
         real(dp) :: weights(4)
         do i = 0, model%elements
            call node_row(model, i, dofs, weights)
            bound(i + 1) = 0
            do a = 1, 4
               if (dofs(a) > 0) bound(i + 1) = bound(i + 1) + abs(weights(a))*v(dofs(a))
            end do
         end do
      end function nodal_magnitude

      subroutine add_row(c, sign_of_row, level, flexibility)
         integer, intent(in) :: c
         real(dp), intent(in) :: sign_of_row, level, flexibility
         r = r + 1
         point(r) = c
         direction(r) = sign_of_row
         level_of_row(r) = level
         compliance(r) = flexibility
      end subroutine add_row
   end subroutine solve_static_band
end module vibrobeam_static_band
