!> Unit test of the contact projection (`contact_projector`, method 'newton'): random
!! bound-constrained QPs
!!
!!     x = argmin 1/2 (x - x_free)^T W (x - x_free),  lower_k <= H_k x <= upper_k,
!!
!! with W a random symmetric positive definite band matrix with 3 sub-diagonals (random
!! signs off the diagonal, so not an M-matrix) or a beam's own metric, and rows H_k that
!! are one unknown (Hermite-like) or three consecutive unknowns with weights 1/6, 2/3, 1/6
!! (B-spline-like); bounds one-sided (the dynamics projection `project`) or two-sided
!! (`project_admissible`), x_free random.
!!
!! References, each computed by an algorithm that shares nothing with the solver under test:
!! - m <= 6: enumeration of every assignment of the points to {lower, free, upper}, each
!!   solved as a dense equality-constrained QP (dense KKT system, LAPACK dgesv); the one
!!   that satisfies every sign and bound is the solution (unique: W is positive definite
!!   and the rows are independent);
!! - one-sided, m up to 1000: the dense LCP of the explicitly formed Delassus matrix
!!   A = S H W^-1 H^T S (W^-1 by dense Cholesky, dpotrf/dpotrs, for J <= 600; by
!!   band solves for larger J) solved by `solve_lcp` (block principal pivoting with
!!   Murty's rule, itself tested against enumeration in test_lcp);
!! - Hermite-like one-sided rows at m = 2000: projected Gauss-Seidel on the primal
!!   problem (coordinate descent with the bounds, Cryer 1971), iterated until a sweep
!!   changes nothing by more than eps.
!!
!! Tolerances (derived): both the solver and a reference compute the same solution, each
!! with the error of a backward-stable linear solve of the optimality system on the held
!! set, at most c_n eps kappa times the size of the solution, with kappa <= cond(W) cond(H H^T)
!! (the Delassus block's condition number) and c_n = 2 (J + m) (the growth of the
!! backward error of an LU or Cholesky factorization of order J + m, Higham ch. 9-10,
!! taken linearly). cond(W) is LAPACK dpbcon's estimate from the Cholesky factor;
!! cond(H H^T) is 1 for unit rows and at most 9 for the B-spline weights (the symbol
!! (2/3 + 1/3 cos w)^2 lies in [1/9, 1]). So |x - x_ref| <= tol (|x_ref| + |x_free|),
!! |P - P_ref| <= tol P_scale with tol = 2 c_n eps kappa and P_scale = max(|P_ref|,
!! |W| |x_ref - x_free|). On the solver's own output: the signs of P exactly; the
!! consistency residual |W x - W x_free - H^T P| <= 2 gamma_9 (|W| (|x| + |x_free|) +
!! |H^T P|) (a residual row has 2 kd + 3 = 9 terms; one refinement step leaves the solve's
!! residual of the same order, Higham Thm 12.3); bounds and complementarity to tol scale.
program test_contact_projection
   use vibrobeam_kinds, only: dp, int64, output_unit
   use vibrobeam_band, only: symmetric_band, band_cholesky, band_allocate, band_add, band_factor, band_entry, &
                             band_matvec, band_solve
   use vibrobeam_contact_set, only: contact_set, contact_value, no_bound
   use vibrobeam_contact_projector, only: contact_projector
   use vibrobeam_model, only: beam_model, build_model, node_row
   use vibrobeam_test_support, only: test_counter, band_abs_times, band_condition, dense_lcp_reference, &
                                     use_program_blas_threads
   use vibrobeam_lapack, only: dgesv
   implicit none


   integer, parameter :: hermite_like = 1, bspline_like = 2
   type(test_counter) :: t
   integer(int64) :: rng = 20260611_int64
   real(dp) :: worst_x = 0, worst_p = 0, worst_residual = 0
   integer :: k, problems = 0, largest_solves = 0, interior_used = 0

   call use_program_blas_threads()
   ! 1. small problems against enumeration: one- and two-sided, both row kinds, both regimes
   do k = 1, 100
      call small_case(1 + mod(k, 2), k <= 50, merge('band    ', 'delassus', mod(k, 3) /= 0))
   end do
   ! 2. one-sided, medium and large, against the dense LCP solver
   call lcp_case(hermite_like, 40, 'band')
   call lcp_case(bspline_like, 40, 'band')
   call lcp_case(hermite_like, 12, 'delassus')
   call lcp_case(bspline_like, 12, 'delassus')
   call lcp_case(hermite_like, 300, 'band')
   call lcp_case(bspline_like, 300, 'band')
   call lcp_case(bspline_like, 1000, 'band')
   ! 3. Hermite-like rows at m = 2000 against projected Gauss-Seidel
   call gauss_seidel_case(2000)
   ! 4. the beam's own metrics (M + theta^2 dt^2 K, and K), both bases, against the dense LCP
   call beam_case('hermite', 24, 1e-3_dp)
   call beam_case('bspline', 24, 1e-3_dp)
   call beam_case('hermite', 64, 1e-2_dp)
   call beam_case('bspline', 64, 1e-2_dp)
   call beam_case('hermite', 16, -1.0_dp)
   call beam_case('bspline', 16, -1.0_dp)
   write (output_unit, '(a,i0,a)') 'test_contact_projection: ', problems, ' problems'
   write (output_unit, '(a,es10.3,a,es10.3,a,es10.3)') '  worst |x - x_ref| / tolerance ', worst_x, &
      ', worst |P - P_ref| / tolerance ', worst_p, ', worst consistency residual / bound ', worst_residual
   write (output_unit, '(a,i0,a,i0,a)') '  largest number of linear solves ', largest_solves, &
      '; the interior-point method ran in ', interior_used, ' problems'
   call t%finish('test_contact_projection')

contains

   !> Uniform in [0, 1) (Park-Miller minimal standard, 64-bit arithmetic).
   real(dp) function uniform()
      rng = mod(16807_int64*rng, 2147483647_int64)
      uniform = real(rng, dp)/2147483647.0_dp
   end function uniform

   !> A random SPD band matrix (3 sub-diagonals): off-diagonal entries uniform in
   !! [-1, 1], each diagonal entry 1 + u plus the absolute sum of its row's off-diagonal
   !! entries (strictly diagonally dominant: eigenvalues in [1, 2 max row sum + 2]).
   function random_metric(n) result(w)
      integer, intent(in) :: n
      type(symmetric_band) :: w
      real(dp) :: row_sum(n), value
      integer :: i, j
      call band_allocate(w, n, 3)
      row_sum = 0
      do j = 1, n
         do i = j + 1, min(n, j + 3)
            value = 2*uniform() - 1
            call band_add(w, i, j, value)
            row_sum(i) = row_sum(i) + abs(value)
            row_sum(j) = row_sum(j) + abs(value)
         end do
      end do
      do i = 1, n
         call band_add(w, i, i, 1 + uniform() + row_sum(i))
      end do
   end function random_metric

   !> m contact points on n unknowns: Hermite-like (unknown 2k - 1) or B-spline-like
   !! (unknowns k, k+1, k+2 with weights 1/6, 2/3, 1/6); bounds unset.
   function random_rows(kind, m, n) result(contacts)
      integer, intent(in) :: kind, m, n
      type(contact_set) :: contacts
      integer :: c
      contacts%count = m
      allocate (contacts%node(m), contacts%x(m), contacts%lower(m), contacts%upper(m), &
                contacts%dofs(4, m), contacts%weights(4, m))
      contacts%dofs = 0
      contacts%weights = 0
      do c = 1, m
         contacts%node(c) = c
         contacts%x(c) = c
         if (kind == hermite_like) then
            contacts%dofs(1, c) = 2*c - 1
            contacts%weights(1, c) = 1
         else
            contacts%dofs(1:3, c) = [c, c + 1, c + 2]
            contacts%weights(1:3, c) = [1.0_dp/6, 2.0_dp/3, 1.0_dp/6]
         end if
      end do
      if (maxval(contacts%dofs) > n) error stop 'random_rows: too few unknowns'
   end function random_rows


   !> |W|_inf.
   real(dp) function norm_inf(w)
      type(symmetric_band), intent(in) :: w
      norm_inf = maxval(band_abs_times(w, [(1.0_dp, k=1, w%n)]))
   end function norm_inf

   !> Solve with the projector: one-sided through `project` (all points, side s_k), or
   !! two-sided through `project_admissible`; returns x and P per point.
   subroutine solve_with_projector(w, contacts, regime, x_free, one_sided, s, x, p)
      type(symmetric_band), intent(in) :: w
      type(contact_set), intent(in) :: contacts
      character(len=*), intent(in) :: regime
      real(dp), intent(in) :: x_free(:), s(:)
      logical, intent(in) :: one_sided
      real(dp), intent(out) :: x(:), p(:)
      type(band_cholesky) :: factor
      type(contact_projector) :: projector
      real(dp) :: bound(contacts%count)
      integer :: stat, iterations, c
      character(len=256) :: errmsg
      call band_factor(w, factor, stat, errmsg)
      if (stat /= 0) error stop 'band_factor failed'
      call projector%setup(w, factor, contacts, regime, 'newton')
      if (one_sided) then
         bound = merge(contacts%lower, contacts%upper, s > 0)
         call projector%project(x_free, [(c, c=1, contacts%count)], s, bound, x, p, iterations, stat, errmsg)
      else
         call projector%project_admissible(x_free, x, p, iterations, stat, errmsg)
      end if
      call t%check_true('projection succeeds', stat == 0, trim(errmsg))
      call t%check_true('no fall-back needed', .not. projector%used_fallback)
      largest_solves = max(largest_solves, projector%linear_solves)
      if (projector%interior_iterations > 0) interior_used = interior_used + 1
   end subroutine solve_with_projector

   !> Compare with a reference and check the solver's own guarantees.
   subroutine compare(label, w, contacts, x_free, one_sided, s, x, p, x_ref, p_ref, kappa)
      character(len=*), intent(in) :: label
      type(symmetric_band), intent(in) :: w
      type(contact_set), intent(in) :: contacts
      real(dp), intent(in) :: x_free(:), s(:), x(:), p(:), x_ref(:), p_ref(:), kappa
      logical, intent(in) :: one_sided
      real(dp) :: tol, p_scale, scale, residual(size(x)), w_x(size(x)), w_free(size(x)), h_p(size(x)), bound, &
                  gamma9, value
      integer :: c, a
      character(len=160) :: detail
      problems = problems + 1
      tol = 2*2*(w%n + contacts%count)*epsilon(1.0_dp)*kappa
      ! x and P against the reference
      write (detail, '(a,es10.3,a,es10.3)') '|x - x_ref| = ', maxval(abs(x - x_ref)), ', tolerance ', &
         tol*(maxval(abs(x_ref)) + maxval(abs(x_free)))
      call t%check_true(label//': x', maxval(abs(x - x_ref)) <= tol*(maxval(abs(x_ref)) + maxval(abs(x_free))), &
                        trim(detail))
      worst_x = max(worst_x, maxval(abs(x - x_ref))/(tol*(maxval(abs(x_ref)) + maxval(abs(x_free)))))
      p_scale = max(maxval(abs(p_ref)), norm_inf(w)*maxval(abs(x_ref - x_free)), tiny(1.0_dp))
      write (detail, '(a,es10.3,a,es10.3)') '|P - P_ref| = ', maxval(abs(p - p_ref)), ', tolerance ', tol*p_scale
      call t%check_true(label//': P', maxval(abs(p - p_ref)) <= tol*p_scale, trim(detail))
      worst_p = max(worst_p, maxval(abs(p - p_ref))/(tol*p_scale))
      ! consistency: W (x - x_free) = H^T P to the round-off of the products
      call band_matvec(w, x, w_x)
      call band_matvec(w, x_free, w_free)
      h_p = 0
      do c = 1, contacts%count
         do a = 1, 4
            if (contacts%dofs(a, c) /= 0) h_p(contacts%dofs(a, c)) = h_p(contacts%dofs(a, c)) + contacts%weights(a, c)*p(c)
         end do
      end do
      residual = w_x - w_free - h_p
      gamma9 = 9*epsilon(1.0_dp)/(1 - 9*epsilon(1.0_dp))
      bound = 2*gamma9*(norm_inf(w)*(maxval(abs(x)) + maxval(abs(x_free))) + maxval(abs(h_p)))
      write (detail, '(a,es10.3,a,es10.3)') '|W (x - x_free) - H^T P| = ', maxval(abs(residual)), ', bound ', bound
      call t%check_true(label//': consistency', maxval(abs(residual)) <= bound, trim(detail))
      worst_residual = max(worst_residual, maxval(abs(residual))/bound)
      ! signs exactly; bounds and complementarity to tol scale
      scale = max(maxval(abs(x)), maxval(abs(x_free)))
      do c = 1, contacts%count
         value = contact_value(contacts, c, x)
         if (one_sided) then
            call t%check_true(label//': s P >= 0 exactly', s(c)*p(c) >= 0)
            bound = merge(contacts%lower(c), contacts%upper(c), s(c) > 0)
            call t%check_true(label//': constraint', s(c)*(value - bound) >= -tol*scale)
            if (abs(p(c)) > 0) call t%check_true(label//': complementarity', abs(value - bound) <= tol*scale)
         else
            call t%check_true(label//': bounds', value >= contacts%lower(c) - tol*scale .and. &
                              value <= contacts%upper(c) + tol*scale)
            if (p(c) > 0) call t%check_true(label//': complementarity (lower)', abs(value - contacts%lower(c)) <= tol*scale)
            if (p(c) < 0) call t%check_true(label//': complementarity (upper)', abs(value - contacts%upper(c)) <= tol*scale)
         end if
      end do
   end subroutine compare

   !> Random x_free (uniform in [-1, 1]), sides (70 % from below) and bounds within 0.6 of
   !! the free values, so that some hold and some do not; two-sided: an upper bound 0.1 to
   !! 0.6 above the lower one, absent for a fifth of the points.
   subroutine random_bounds(contacts, n, one_sided, x_free, s)
      type(contact_set), intent(inout) :: contacts
      integer, intent(in) :: n
      logical, intent(in) :: one_sided
      real(dp), allocatable, intent(out) :: x_free(:), s(:)
      integer :: c
      allocate (x_free(n), s(contacts%count))
      do c = 1, n
         x_free(c) = 2*uniform() - 1
      end do
      do c = 1, contacts%count
         s(c) = merge(1.0_dp, -1.0_dp, uniform() < 0.7_dp)
         contacts%lower(c) = contact_value(contacts, c, x_free) + 0.6_dp*(2*uniform() - 1)
         contacts%upper(c) = contacts%lower(c) + 0.1_dp + 0.5_dp*uniform()
         if (one_sided) then
            if (s(c) > 0) contacts%upper(c) = no_bound
            if (s(c) < 0) contacts%lower(c) = -no_bound
         else if (uniform() < 0.2_dp) then
            contacts%upper(c) = no_bound   ! a point with one side only
         end if
      end do
   end subroutine random_bounds

   !> A small random problem against enumeration.
   subroutine small_case(kind, one_sided, regime)
      integer, intent(in) :: kind
      logical, intent(in) :: one_sided
      character(len=*), intent(in) :: regime
      type(symmetric_band) :: w
      type(contact_set) :: contacts
      real(dp), allocatable :: x_free(:), s(:), x(:), p(:), x_ref(:), p_ref(:)
      integer :: m, n
      m = 2 + int(5*uniform())
      n = merge(2*m + 2, m + 3, kind == hermite_like)
      w = random_metric(n)
      contacts = random_rows(kind, m, n)
      allocate (x(n), p(m), x_ref(n), p_ref(m))
      call random_bounds(contacts, n, one_sided, x_free, s)
      call solve_with_projector(w, contacts, regime, x_free, one_sided, s, x, p)
      call enumerate(w, contacts, x_free, x_ref, p_ref)
      call compare('small '//trim(merge('hermite-like', 'bspline-like', kind == hermite_like))//' '// &
                   trim(merge('one-sided', 'two-sided', one_sided))//' '//trim(regime), &
                   w, contacts, x_free, one_sided, s, x, p, x_ref, p_ref, &
                   band_condition(w)*merge(1, 9, kind == hermite_like))
   end subroutine small_case

   !> Every assignment of the points to {lower, free, upper}, each an equality-constrained
   !! dense QP (dgesv on the KKT matrix); keep the one that satisfies every sign and bound
   !! with the smallest violation.
   subroutine enumerate(w, contacts, x_free, x_ref, p_ref)
      type(symmetric_band), intent(in) :: w
      type(contact_set), intent(in) :: contacts
      real(dp), intent(in) :: x_free(:)
      real(dp), intent(out) :: x_ref(:), p_ref(:)
      integer :: m, n, code, c, i, j, nf, info, side(contacts%count)
      real(dp), allocatable :: kkt(:, :), rhs(:)
      integer, allocatable :: pivots(:), held(:)
      real(dp) :: best, violation, value, w_free(size(x_free)), scale
      m = contacts%count
      n = w%n
      call band_matvec(w, x_free, w_free)
      best = huge(1.0_dp)
      scale = maxval(abs(x_free)) + 1
      do code = 0, 3**m - 1
         do c = 1, m
            side(c) = mod(code/3**(c - 1), 3) - 1
         end do
         if (any(side == 1 .and. contacts%lower <= -no_bound) .or. any(side == -1 .and. contacts%upper >= no_bound)) cycle
         held = pack([(c, c=1, m)], side /= 0)
         nf = size(held)
         allocate (kkt(n + nf, n + nf), rhs(n + nf), pivots(n + nf))
         kkt = 0
         do j = 1, n
            do i = 1, n
               kkt(i, j) = band_entry(w, i, j)
            end do
         end do
         do i = 1, nf
            do j = 1, 4
               if (contacts%dofs(j, held(i)) == 0) cycle
               kkt(contacts%dofs(j, held(i)), n + i) = -contacts%weights(j, held(i))
               kkt(n + i, contacts%dofs(j, held(i))) = -contacts%weights(j, held(i))
            end do
            rhs(n + i) = -merge(contacts%lower(held(i)), contacts%upper(held(i)), side(held(i)) == 1)
         end do
         rhs(1:n) = w_free
         call dgesv(n + nf, 1, kkt, n + nf, pivots, rhs, n + nf, info)
         if (info == 0) then
            violation = 0
            do i = 1, nf
               violation = max(violation, -side(held(i))*rhs(n + i)/scale)
            end do
            do c = 1, m
               if (side(c) /= 0) cycle
               value = contact_value(contacts, c, rhs(1:n))
               violation = max(violation, (contacts%lower(c) - value)/scale, (value - contacts%upper(c))/scale)
            end do
            if (violation < best) then
               best = violation
               x_ref = rhs(1:n)
               p_ref = 0
               p_ref(held) = rhs(n + 1:n + nf)
            end if
         end if
         deallocate (kkt, rhs, pivots)
      end do
      call t%check_true('enumeration finds a solution', best <= 1e-10_dp)
   end subroutine enumerate

   !> One-sided problem of m points against the dense LCP of the Delassus matrix.
   subroutine lcp_case(kind, m, regime)
      integer, intent(in) :: kind, m
      character(len=*), intent(in) :: regime
      type(symmetric_band) :: w
      type(contact_set) :: contacts
      real(dp), allocatable :: x_free(:), s(:), x(:), p(:), x_ref(:), p_ref(:)
      integer :: n
      character(len=32) :: label
      n = merge(2*m + 2, m + 3, kind == hermite_like)
      w = random_metric(n)
      contacts = random_rows(kind, m, n)
      allocate (x(n), p(m), x_ref(n), p_ref(m))
      call random_bounds(contacts, n, .true., x_free, s)
      call solve_with_projector(w, contacts, regime, x_free, .true., s, x, p)
      call lcp_reference(w, contacts, x_free, s, x_ref, p_ref)
      write (label, '(a,i0,a)') 'LCP reference, m = ', m, ' '//trim(regime)
      call compare(trim(label), w, contacts, x_free, .true., s, x, p, x_ref, p_ref, &
                   band_condition(w)*merge(1, 9, kind == hermite_like))
   end subroutine lcp_case

   !> The dense LCP reference (`dense_lcp_reference`, test_support).
   subroutine lcp_reference(w, contacts, x_free, s, x_ref, p_ref)
      type(symmetric_band), intent(in) :: w
      type(contact_set), intent(in) :: contacts
      real(dp), intent(in) :: x_free(:), s(:)
      real(dp), intent(out) :: x_ref(:), p_ref(:)
      integer :: stat
      character(len=256) :: errmsg
      call dense_lcp_reference(w, contacts, s, x_ref, p_ref, stat, errmsg, x_free=x_free)
      call t%check_true('dense LCP reference solves', stat == 0, trim(errmsg))
   end subroutine lcp_reference

   !> Hermite-like one-sided rows at m points against projected Gauss-Seidel on x.
   subroutine gauss_seidel_case(m)
      integer, intent(in) :: m
      type(symmetric_band) :: w
      type(contact_set) :: contacts
      real(dp), allocatable :: x_free(:), s(:), x(:), p(:), x_ref(:), p_ref(:), w_free(:), w_x(:)
      real(dp) :: change, value, lower_x, upper_x, diagonal
      integer :: n, c, i, j, sweep
      integer, allocatable :: point_of(:)
      n = 2*m + 2
      w = random_metric(n)
      contacts = random_rows(hermite_like, m, n)
      allocate (x_free(n), s(m), x(n), p(m), x_ref(n), p_ref(m), w_free(n), w_x(n), point_of(n))
      do c = 1, n
         x_free(c) = 2*uniform() - 1
      end do
      point_of = 0
      do c = 1, m
         s(c) = merge(1.0_dp, -1.0_dp, uniform() < 0.7_dp)
         contacts%lower(c) = x_free(2*c - 1) + 0.6_dp*(2*uniform() - 1)
         contacts%upper(c) = contacts%lower(c)
         if (s(c) > 0) contacts%upper(c) = no_bound
         if (s(c) < 0) contacts%lower(c) = -no_bound
         point_of(2*c - 1) = c
      end do
      call solve_with_projector(w, contacts, 'band', x_free, .true., s, x, p)
      ! coordinate descent: x_i = clamp((W x_free - sum_{j /= i} W_ij x_j)_i / W_ii)
      call band_matvec(w, x_free, w_free)
      x_ref = x_free
      do sweep = 1, 100000
         change = 0
         do i = 1, n
            value = w_free(i)
            do j = max(1, i - w%kd), min(n, i + w%kd)
               if (j /= i) value = value - band_entry(w, i, j)*x_ref(j)
            end do
            diagonal = band_entry(w, i, i)
            value = value/diagonal
            if (point_of(i) > 0) then
               lower_x = contacts%lower(point_of(i))
               upper_x = contacts%upper(point_of(i))
               value = min(max(value, lower_x), upper_x)
            end if
            change = max(change, abs(value - x_ref(i)))
            x_ref(i) = value
         end do
         if (change <= 4*epsilon(1.0_dp)*maxval(abs(x_ref))) exit
      end do
      call band_matvec(w, x_ref, w_x)
      ! P = W (x - x_free) on the constrained rows (zero, to the convergence, where free)
      p_ref = [(w_x(2*c - 1) - w_free(2*c - 1), c=1, m)]
      call compare('projected Gauss-Seidel reference, m = 2000', w, contacts, x_free, .true., s, x, p, x_ref, p_ref, &
                   band_condition(w))
   end subroutine gauss_seidel_case

   !> The beam's own metric (dt > 0: M + (dt/2)^2 K; dt < 0: K) with a floor at every node
   !! at a random level near the free values, one-sided, against the dense LCP.
   subroutine beam_case(basis, elements, dt)
      character(len=*), intent(in) :: basis
      integer, intent(in) :: elements
      real(dp), intent(in) :: dt
      type(beam_model) :: model
      type(symmetric_band) :: w
      type(contact_set) :: contacts
      real(dp), allocatable :: x_free(:), s(:), x(:), p(:), x_ref(:), p_ref(:)
      integer :: c, stat
      character(len=128) :: errmsg
      character(len=48) :: label
      call build_model(basis, elements, 1.0_dp, 1.0_dp, 1.0_dp, model, stat, errmsg)
      if (dt > 0) then
         w = model%mass
         w%lower = model%mass%lower + 0.25_dp*dt**2*model%stiffness%lower
      else
         w = model%stiffness
      end if
      contacts%count = elements
      allocate (contacts%node(elements), contacts%x(elements), contacts%lower(elements), contacts%upper(elements), &
                contacts%dofs(4, elements), contacts%weights(4, elements))
      allocate (x_free(model%unknowns), s(elements), x(model%unknowns), p(elements), x_ref(model%unknowns), &
                p_ref(elements))
      do c = 1, model%unknowns
         x_free(c) = 2*uniform() - 1
      end do
      do c = 1, elements
         contacts%node(c) = c
         contacts%x(c) = model%x(c + 1)
         call node_row(model, c, contacts%dofs(:, c), contacts%weights(:, c))
         s(c) = 1
         contacts%lower(c) = contact_value(contacts, c, x_free) + 0.5_dp*(2*uniform() - 1)
         contacts%upper(c) = no_bound
      end do
      call solve_with_projector(w, contacts, 'band', x_free, .true., s, x, p)
      call lcp_reference(w, contacts, x_free, s, x_ref, p_ref)
      write (label, '(a,i0,a)') 'beam metric '//basis//', N = ', elements, merge(' (dynamics)', ' (statics) ', dt > 0)
      call compare(trim(label), w, contacts, x_free, .true., s, x, p, x_ref, p_ref, &
                   band_condition(w)*merge(1, 9, basis == 'hermite'))
   end subroutine beam_case
end program test_contact_projection
