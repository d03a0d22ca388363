!> Static equilibrium of the clamped-free beam held at some of its nodes, computed in
!! curvatures, without factoring K (docs/method.md "Statics"; theory §5 "Statics").
!!
!! Why. K discretizes a fourth-order operator: cond(K) ~ N^4 (1e22 at N = 1e5), and any
!! solve that factors K, or a matrix that contains it (the held problem's K_RR, the
!! Delassus matrix H K^-1 H^T of a floor), loses digits like N^4 on smooth data. In the
!! curvature space of `vibrobeam_flexibility` (U = T z, energy 1/2 z^T G z, G = EI times the
!! mass matrix of piecewise linears) the held problem has a well-conditioned form:
!!
!! the nodes X_1 < ... < X_m are held at w(X_j) = t_j (X_0 = 0 the clamp). Let B_0 be the
!! linear function from 1 at X_0 to 0 at X_1, and B_j (1 <= j <= m-1) the hat on
!! [X_(j-1), X_j, X_(j+1)]. They lie in the curvature space (their breaks are nodes), and
!! for every u of the discrete space, clamped at 0, integrating by parts twice,
!!
!!     int B_0 u'' = t_1/L_1,
!!     int B_j u'' = (t_(j+1) - t_j)/L_(j+1) - (t_j - t_(j-1))/L_j =: c_j,   L_j = X_j - X_(j-1):
!!
!! m linear combinations of the held values (t_0 = 0), equivalent to them, whose rows
!! C = B^T Mass act on z locally. With these as the constraints, the Lagrange conditions
!! G z = T^T f + C^T lambda give z = kappa_free + (sum lambda_j B_j)/EI, kappa_free =
!! G^-1 T^T f: lambda_j is the bending moment of the reactions at X_j (0 at X_m), and
!!
!!     S lambda = EI (c - int B kappa_free),    S = B^T Mass B,
!!
!! S the mass matrix of the piecewise linears on the held nodes: tridiagonal, L_j/6 and
!! (L_j + L_(j+1))/3, diagonally dominant, condition number at most 3 after diagonal scaling
!! whatever the spans. The reactions, P = D_c^T lambda (D_c the map from held values to c),
!! are the changes of slope of the moment line at the held nodes:
!!
!!     P_j = (lambda_(j-1) - lambda_j)/L_j - (lambda_j - lambda_(j+1))/L_(j+1),   lambda_m = 0,
!!
!! positive upwards, so that K U = F + H^T P. Everything else is sums: the integrals of the
!! free curvature against the B_j, element by element, and U = T z. Cost O(J + m), no
!! factorization of order J. The same holds for both bases: the B_j lie in both curvature
!! spaces, and H_c U is the value of u at node c in both.
!!
!! Elastic supports. A held node may instead be elastic, w_j = t_j - c_j P_j with compliance
!! c_j > 0 (a linearized compliant stop): then D_c w = D_c t - D_c diag(c) D_c^T lambda and
!!
!!     (S + EI D_c diag(c) D_c^T) lambda = EI (D_c t - int B kappa_free),
!!
!! pentadiagonal (LAPACK dpbtrf, two sub-diagonals). Stiff supports (c_j EI/L_j^3 << 1) keep
!! the condition number of S; soft ones over many short spans raise it towards that of a
!! fourth difference, and the caller's a-posteriori check says when that cost accuracy.
!!
!! Round-off: S has condition <= 3; the right-hand side is a sum over elements of the free
!! curvature, whose error is that of `vibrobeam_flexibility`; so lambda errs by about
!! eps N times the largest bending moment, U by about eps N times the deflections (the
!! a-posteriori check of `vibrobeam_static` bounds it), and each reaction by about eps N
!! times the largest moment divided by its spans: relative to the total load |q| L, eps N.
module vibrobeam_support_moments
   use vibrobeam_kinds, only: dp
   use vibrobeam_status, only: stat_linear_solver_failure
   use vibrobeam_lapack, only: dpttrf, dpttrs, dpbtrf, dpbtrs, dpbcon
   use vibrobeam_flexibility, only: cantilever_flexibility
   implicit none
   private
   public :: held_equilibrium, add_moment_line

contains

   !> The equilibrium under the loads whose free curvature is `free_curvature`
   !! (`curvature_of_loads`) with the nodes `nodes` (increasing, in 1..N) held at `targets`
   !! (rigidly, or elastically where `compliance` > 0), and first-order bounds of its
   !! round-off (u = eps/2, gamma_n = n u/(1 - n u); Higham, Accuracy and Stability of
   !! Numerical Algorithms, 2002):
   !! - the right-hand side: the free curvature's own error `curvature_error` integrated
   !!   against B_j, the sums over the n_j elements under B_j (gamma_(n_j + 6) of the same
   !!   integral of |kappa_free|), c_j (gamma_3 of its terms, each difference of targets
   !!   rounded relative to itself) and the product by EI;
   !! - the solve with S (tridiagonal, positive, backward error gamma_4 S): |S^-1| <=
   !!   (D_S - O_S)^-1 (Neumann series, ||D_S^-1 O_S|| <= 1/2), so |d lambda| <=
   !!   (D_S - O_S)^-1 (|d rhs| + gamma_4 S |lambda|); with elastic supports, normwise,
   !!   with LAPACK dpbcon's estimate of ||A^-1||_1;
   !! - each reaction: the rounding of its two differences (`reaction_rounding`, gamma_6 of
   !!   |lambda| over the spans) plus |D_c^T| |d lambda| (`reaction_error`, both).
   !! stat /= 0 only if the moment equations cannot be factored (nodes not increasing).
   subroutine held_equilibrium(flexibility, free_curvature, curvature_error, nodes, targets, compliance, z, u, reaction, &
                               moment, moment_error, reaction_rounding, reaction_error, stat, errmsg)
      type(cantilever_flexibility), intent(in) :: flexibility
      real(dp), intent(in) :: free_curvature(:)  !! (J) G^-1 T^T F (1/m)
      real(dp), intent(in) :: curvature_error(:) !! (J) bound of the error of free_curvature (1/m)
      integer, intent(in) :: nodes(:)            !! (m) held nodes, increasing, in 1..N
      real(dp), intent(in) :: targets(:)         !! (m) their displacements t_j (m)
      real(dp), intent(in) :: compliance(:)      !! (m) c_j >= 0 (m/N): w_j = t_j - c_j P_j; 0 rigid
      real(dp), intent(out) :: z(:)              !! (J) curvature of the equilibrium (1/m)
      real(dp), intent(out) :: u(:)              !! (J) its unknowns U = T z
      real(dp), intent(out) :: reaction(:)       !! (m) P_j (N, per unit mass with k2), positive upwards
      real(dp), intent(out) :: moment(0:)        !! (0:m) lambda_j (N m), moment(m) = 0
      real(dp), intent(out) :: moment_error(0:)  !! (0:m) bound of the error of lambda_j (N m)
      real(dp), intent(out) :: reaction_rounding(:) !! (m) bound of the rounding of P_j formed from lambda (N)
      real(dp), intent(out) :: reaction_error(:) !! (m) bound of the error of P_j (N)
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      real(dp), allocatable :: span(:), diagonal(:), off_diagonal(:), rhs(:), rhs_error(:)
      integer :: m
      stat = 0
      errmsg = ''
      m = size(nodes)
      z = free_curvature
      moment = 0
      moment_error = 0
      if (m == 0) then
         call flexibility%displacement_of_curvature(z, u)
         return
      end if
      allocate (span(m), diagonal(m), off_diagonal(max(m - 1, 1)), rhs(m), rhs_error(m), source=0.0_dp)
      call moment_equations(flexibility, nodes, targets, free_curvature, curvature_error, span, diagonal, &
                            off_diagonal, rhs, rhs_error)
      if (any(compliance > 0)) then
         call solve_elastic(flexibility%ei, span, compliance, diagonal, off_diagonal, rhs, rhs_error, &
                            moment(0:m - 1), moment_error(0:m - 1), stat, errmsg)
      else
         call solve_rigid(span, diagonal, off_diagonal, rhs, rhs_error, moment(0:m - 1), moment_error(0:m - 1), &
                          stat, errmsg)
      end if
      if (stat /= 0) return
      moment(m) = 0
      ! z = kappa_free + (moment line)/EI on [0, X_m]; 0 beyond
      call add_moment_line(flexibility, nodes, moment(0:m - 1)/flexibility%ei, z)
      call flexibility%displacement_of_curvature(z, u)
      call moment_reactions(span, moment, moment_error, reaction, reaction_rounding, reaction_error)
   end subroutine held_equilibrium

   !> The moment equations S lambda = EI (c - int B kappa_free) of the held nodes (module
   !! documentation): the spans L_j, S (its diagonal and off-diagonal), the right-hand side
   !! (row j = 0..m-1 at rhs(j + 1)) and the bound of its error (`held_equilibrium`).
   subroutine moment_equations(flexibility, nodes, targets, free_curvature, curvature_error, span, diagonal, &
                               off_diagonal, rhs, rhs_error)
      type(cantilever_flexibility), intent(in) :: flexibility
      integer, intent(in) :: nodes(:)
      real(dp), intent(in) :: targets(:), free_curvature(:), curvature_error(:)
      real(dp), intent(out) :: span(:), diagonal(:), off_diagonal(:), rhs(:), rhs_error(:)
      real(dp) :: magnitude_int(size(nodes)), error_int(size(nodes))
      integer :: elements_under(size(nodes))
      integer :: m, j
      m = size(nodes)
      ! spans, S and c (rhs(j + 1) holds row j = 0..m-1), with the rounding of c
      span(1) = flexibility%position(nodes(1)) - flexibility%position(0)
      do j = 2, m
         span(j) = flexibility%position(nodes(j)) - flexibility%position(nodes(j - 1))
      end do
      diagonal(1) = span(1)/3
      rhs(1) = targets(1)/span(1)
      rhs_error(1) = rounding_gamma(2)*abs(rhs(1))
      do j = 2, m
         diagonal(j) = (span(j - 1) + span(j))/3
         off_diagonal(j - 1) = span(j - 1)/6
         rhs(j) = (targets(j) - targets(j - 1))/span(j) - (targets(j - 1) - previous_target(j - 1))/span(j - 1)
         ! each difference of targets is rounded relative to itself (IEEE subtraction)
         rhs_error(j) = rounding_gamma(3)*(abs(targets(j) - targets(j - 1))/span(j) + &
                                           abs(targets(j - 1) - previous_target(j - 1))/span(j - 1))
      end do
      call integrate_free_curvature(flexibility, nodes, span, free_curvature, curvature_error, rhs, magnitude_int, &
                                    error_int, elements_under)
      do j = 1, m
         rhs_error(j) = flexibility%ei*(rhs_error(j) + error_int(j) + rounding_gamma(elements_under(j) + 8)*magnitude_int(j)) + &
                        rounding_gamma(2)*flexibility%ei*abs(rhs(j))
      end do
      rhs = flexibility%ei*rhs
   contains
      real(dp) function previous_target(j)
         integer, intent(in) :: j
         previous_target = 0
         if (j > 1) previous_target = targets(j - 1)
      end function previous_target
   end subroutine moment_equations

   !> rhs(j) -= int B_(j-1) kappa_free, element by element: span j (from X_(j-1) to X_j)
   !! carries the falling part of B_(j-1) (row j) and the rising part of B_j (row j + 1,
   !! if j < m); with the same integrals of |kappa_free| (`magnitude_int`) and of its
   !! error bound (`error_int`), and the elements under each B (`elements_under`).
   subroutine integrate_free_curvature(flexibility, nodes, span, free_curvature, curvature_error, rhs, magnitude_int, &
                                       error_int, elements_under)
      type(cantilever_flexibility), intent(in) :: flexibility
      integer, intent(in) :: nodes(:)
      real(dp), intent(in) :: span(:), free_curvature(:), curvature_error(:)
      real(dp), intent(inout) :: rhs(:)
      real(dp), intent(out) :: magnitude_int(:), error_int(:)
      integer, intent(out) :: elements_under(:)
      real(dp) :: start, finish, left, right, rise(2), fall(2), kappa(2), kappa_abs(2), kappa_err(2), length
      integer :: m, j, e
      m = size(nodes)
      magnitude_int = 0
      error_int = 0
      elements_under = 0
      do j = 1, m
         start = flexibility%position(merge(0, nodes(max(j - 1, 1)), j == 1))
         finish = flexibility%position(nodes(j))
         do e = merge(1, nodes(max(j - 1, 1)) + 1, j == 1), nodes(j)
            left = flexibility%position(e - 1)
            right = flexibility%position(e)
            length = right - left
            kappa = free_curvature(flexibility%curvature_index(e, [1, 2]))
            kappa_abs = abs(kappa)
            kappa_err = curvature_error(flexibility%curvature_index(e, [1, 2]))
            rise = [(left - start)/span(j), (right - start)/span(j)]
            fall = [(finish - left)/span(j), (finish - right)/span(j)]
            rhs(j) = rhs(j) - linear_product(length, kappa, fall)
            magnitude_int(j) = magnitude_int(j) + linear_product(length, kappa_abs, fall)
            error_int(j) = error_int(j) + linear_product(length, kappa_err, fall)
            elements_under(j) = elements_under(j) + 1
            if (j < m) then
               rhs(j + 1) = rhs(j + 1) - linear_product(length, kappa, rise)
               magnitude_int(j + 1) = magnitude_int(j + 1) + linear_product(length, kappa_abs, rise)
               error_int(j + 1) = error_int(j + 1) + linear_product(length, kappa_err, rise)
               elements_under(j + 1) = elements_under(j + 1) + 1
            end if
         end do
      end do
   end subroutine integrate_free_curvature

   !> Rigid supports: lambda = S^-1 rhs (tridiagonal, LAPACK dpttrf/dpttrs) and the
   !! bound of its error, |d lambda| <= (D_S - O_S)^-1 (|d rhs| + gamma_4 S |lambda|).
   subroutine solve_rigid(span, diagonal, off_diagonal, rhs, rhs_error, moment, moment_error, stat, errmsg)
      real(dp), intent(in) :: span(:), rhs(:), rhs_error(:)
      real(dp), intent(inout), contiguous :: diagonal(:), off_diagonal(:)   !! S; overwritten by its factor
      real(dp), intent(out), contiguous :: moment(:)          !! (m) lambda_0 .. lambda_(m-1)
      real(dp), intent(out) :: moment_error(:)                 !! (m) bound of their errors
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      real(dp) :: bound_diagonal(size(diagonal)), bound_off(size(off_diagonal)), absolute(size(rhs))
      integer :: m, info
      m = size(rhs)
      bound_diagonal = diagonal
      bound_off = -off_diagonal
      moment = rhs
      call dpttrf(m, diagonal, off_diagonal, info)
      if (info == 0) call dpttrs(m, 1, diagonal, off_diagonal, moment, m, info)
      call check_info(info, stat, errmsg)
      if (stat /= 0) return
      absolute = rhs_error + rounding_gamma(4)*tridiagonal_abs_times(span, abs(moment))
      call dpttrf(m, bound_diagonal, bound_off, info)
      if (info == 0) call dpttrs(m, 1, bound_diagonal, bound_off, absolute, m, info)
      moment_error = abs(absolute)
   end subroutine solve_rigid

   !> Elastic supports: lambda = (S + EI D_c diag(c) D_c^T)^-1 rhs (pentadiagonal, LAPACK
   !! dpbtrf/dpbtrs) and the bound of its error, normwise with dpbcon's estimate of
   !! ||A^-1||_1: (max |d rhs| + gamma_5 |A| max |lambda|) ||A^-1||.
   subroutine solve_elastic(ei, span, compliance, diagonal, off_diagonal, rhs, rhs_error, moment, moment_error, stat, &
                            errmsg)
      real(dp), intent(in) :: ei, span(:), compliance(:), diagonal(:), off_diagonal(:), rhs(:), rhs_error(:)
      real(dp), intent(out), contiguous :: moment(:)          !! (m) lambda_0 .. lambda_(m-1)
      real(dp), intent(out) :: moment_error(:)                 !! (m) bound of their errors
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      real(dp), allocatable :: band(:, :), work(:)
      integer, allocatable :: iwork(:)
      real(dp) :: column(3), norm_a, rcond
      integer :: m, j, k, r, info
      m = size(rhs)
      ! S + EI D_c diag(c) D_c^T in lower band storage (2 sub-diagonals): column i of D_c
      ! (held node i) has 1/L_i in row i-1, -(1/L_i + 1/L_(i+1)) in row i, 1/L_(i+1) in
      ! row i+1 (rows 0..m-1 stored at 1..m)
      allocate (band(3, m), source=0.0_dp)
      band(1, :) = diagonal
      band(2, 1:m - 1) = off_diagonal(1:m - 1)
      do j = 1, m
         if (.not. compliance(j) > 0) cycle
         column = [1/span(j), -(1/span(j) + 1/span(min(j + 1, m))), 1/span(min(j + 1, m))]
         if (j == m) column(2:3) = 0
         if (j == m - 1) column(3) = 0
         ! rows j-1, j, j+1 of D_c are stored at j, j+1, j+2
         do k = 1, 3
            do r = k, 3
               if (j + r - 1 > m) cycle
               band(r - k + 1, j + k - 1) = band(r - k + 1, j + k - 1) + ei*compliance(j)*column(r)*column(k)
            end do
         end do
      end do
      norm_a = 0
      do j = 1, m
         norm_a = max(norm_a, sum(abs(band(:, j))) + sum([(abs(band(k + 1, j - k)), k=1, min(2, j - 1))]))
      end do
      moment = rhs
      call dpbtrf('L', m, 2, band, 3, info)
      if (info == 0) then
         allocate (work(3*m), iwork(m))
         call dpbcon('L', m, 2, band, 3, norm_a, rcond, work, iwork, info)
      end if
      if (info == 0) call dpbtrs('L', m, 2, 1, band, 3, moment, m, info)
      call check_info(info, stat, errmsg)
      if (stat /= 0) return
      moment_error = (maxval(rhs_error) + rounding_gamma(5)*norm_a*maxval(abs(moment)))/max(rcond*norm_a, tiny(1.0_dp))
   end subroutine solve_elastic

   !> stat_linear_solver_failure with a message when LAPACK's `info` is not 0.
   subroutine check_info(info, stat, errmsg)
      integer, intent(in) :: info
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      stat = 0
      errmsg = ''
      if (info == 0) return
      stat = stat_linear_solver_failure
      write (errmsg, '(a,i0,a)') 'held equilibrium: the moment equations (LAPACK) failed, info = ', info, &
         ' (held nodes must increase)'
   end subroutine check_info

   !> The reactions, the changes of slope of the moment line at the held nodes (module
   !! documentation), with the bounds of their rounding and of their error.
   pure subroutine moment_reactions(span, moment, moment_error, reaction, reaction_rounding, reaction_error)
      real(dp), intent(in) :: span(:), moment(0:), moment_error(0:)
      real(dp), intent(out) :: reaction(:), reaction_rounding(:), reaction_error(:)
      integer :: m, j
      m = size(span)
      do j = 1, m
         reaction(j) = (moment(j - 1) - moment(j))/span(j)
         reaction_rounding(j) = (abs(moment(j - 1)) + abs(moment(j)))/span(j)
         reaction_error(j) = (moment_error(j - 1) + moment_error(j))/span(j)
         if (j < m) then
            reaction(j) = reaction(j) - (moment(j) - moment(j + 1))/span(j + 1)
            reaction_rounding(j) = reaction_rounding(j) + (abs(moment(j)) + abs(moment(j + 1)))/span(j + 1)
            reaction_error(j) = reaction_error(j) + (moment_error(j) + moment_error(j + 1))/span(j + 1)
         end if
      end do
      reaction_rounding = rounding_gamma(6)*reaction_rounding
      reaction_error = reaction_error + reaction_rounding
   end subroutine moment_reactions

   !> z = z + the piecewise linear function with values(j) at X_j (j = 0..m-1, X_0 = 0),
   !! 0 at X_m = node(m) and beyond, in the curvature space of `flexibility`.
   subroutine add_moment_line(flexibility, nodes, values, z)
      type(cantilever_flexibility), intent(in) :: flexibility
      integer, intent(in) :: nodes(:)          !! (m) held nodes, increasing
      real(dp), intent(in) :: values(0:)       !! (0:m-1)
      real(dp), intent(inout) :: z(:)          !! (J)
      real(dp) :: start, span, line(2), low, high
      integer :: j, e, m
      m = size(nodes)
      do j = 1, m
         start = flexibility%position(merge(0, nodes(max(j - 1, 1)), j == 1))
         span = flexibility%position(nodes(j)) - start
         low = values(j - 1)
         high = 0
         if (j < m) high = values(j)
         do e = merge(1, nodes(max(j - 1, 1)) + 1, j == 1), nodes(j)
            line = [low + (high - low)*(flexibility%position(e - 1) - start)/span, &
                    low + (high - low)*(flexibility%position(e) - start)/span]
            ! B-splines: the curvature is continuous, one value per node (the left end of
            ! each element; the right end of the last is X_m, where the line is 0)
            z(flexibility%curvature_index(e, 1)) = z(flexibility%curvature_index(e, 1)) + line(1)
            if (flexibility%hermite) z(flexibility%curvature_index(e, 2)) = z(flexibility%curvature_index(e, 2)) + line(2)
         end do
      end do
   end subroutine add_moment_line

   !> gamma_n = n u/(1 - n u), u = eps/2.
   pure real(dp) function rounding_gamma(n)
      integer, intent(in) :: n
      rounding_gamma = n*0.5_dp*epsilon(1.0_dp)/(1 - n*0.5_dp*epsilon(1.0_dp))
   end function rounding_gamma

   !> S |x| for S the mass matrix of the piecewise linears on the held nodes (spans L_j).
   pure function tridiagonal_abs_times(span, x) result(y)
      real(dp), intent(in) :: span(:), x(:)
      real(dp) :: y(size(x))
      integer :: j, m
      m = size(x)
      y(1) = span(1)/3*x(1)
      do j = 2, m
         y(j) = (span(j - 1) + span(j))/3*x(j) + span(j - 1)/6*x(j - 1)
         y(j - 1) = y(j - 1) + span(j - 1)/6*x(j)
      end do
   end function tridiagonal_abs_times

   !> int over an element of length h of kappa times phi, both linear with end values
   !! kappa(1:2), phi(1:2): exact.
   pure real(dp) function linear_product(h, kappa, phi)
      real(dp), intent(in) :: h, kappa(2), phi(2)
      linear_product = h/6*(2*kappa(1)*phi(1) + kappa(1)*phi(2) + kappa(2)*phi(1) + 2*kappa(2)*phi(2))
   end function linear_product
end module vibrobeam_support_moments
