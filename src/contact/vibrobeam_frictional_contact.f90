!> The frictional contact problem of one step of the velocity scheme in two dimensions
!! (one normal and one tangent per contact point), solved exactly as a linear
!! complementarity problem by Lemke's method (docs/method.md, "Frictional contact in two
!! dimensions: the solver").
!!
!! Local problem of m contacts, interleaved per contact i: u_i = (u_N, u_T) the local
!! velocity, r_i = (p, r_T) the impulse, at entries 2i-1 (normal) and 2i (tangent):
!!
!!     u = D r + q,
!!     0 <= p  _|_  u_N >= 0                          (Signorini at velocity level)
!!     u_T = 0  =>  |r_T| <= mu p                     (stick)
!!     u_T /= 0 =>  r_T = -mu p sign(u_T)             (slip)
!!
!! with D = H W^-1 H^T the (2m x 2m) Delassus matrix, symmetric positive semidefinite, and
!! q the free local velocity, which includes Newton's restitution term (q_N + e u_N^-).
!!
!! Formulation (Stewart & Trinkle, Int. J. Numer. Methods Eng. 39 (1996) 2673-2691): in 2-D
!! the friction cone {|r_T| <= mu p} is polyhedral, so with r_T = beta+ - beta- and the
!! sliding speed lambda the law is exactly the LCP
!!
!!     0 <= p      _|_  u_N                   >= 0
!!     0 <= beta+  _|_  lambda + u_T          >= 0
!!     0 <= beta-  _|_  lambda - u_T          >= 0
!!     0 <= lambda _|_  mu p - beta+ - beta-  >= 0
!!
!! whose matrix is copositive (z^T M z = x^T G x + sum mu lambda p with G PSD) and, when
!! D r = 0 for r in the cone implies q^T r >= 0 (always so for q in the range of H, i.e.
!! the scheme's q = H v), meets the condition under which Lemke's method ends with a
!! solution (Cottle, Pang & Stone 1992, Theorem 4.4.13; Anitescu & Potra, Nonlinear
!! Dynam. 14 (1997) 231-247). Contacts with mu = 0 carry no beta and lambda.
module vibrobeam_frictional_contact
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use vibrobeam_kinds, only: dp
   use vibrobeam_status, only: fail => set_failure, stat_invalid_argument, stat_residual_check_failed
   use vibrobeam_lemke, only: solve_lemke
   implicit none
   private
   public :: solve_frictional_contact, coulomb_residual

   integer, parameter, public :: contact_separating = 0  !! p = 0
   integer, parameter, public :: contact_sticking = 1    !! p > 0, u_T = 0 (|r_T| <= mu p)
   !> p > 0, r_T = -mu p sign(u_T) with u_T /= 0; also every closed contact with mu = 0
   integer, parameter, public :: contact_slipping = 2

   !> Default relative tolerance of the final check (`coulomb_residual`).
   real(dp), parameter :: default_tolerance = 1.0e-10_dp
   integer, parameter :: buffer_length = 512

   !> The solution of one frictional contact problem and what its solve did.
   type, public :: frictional_contact_solution
      real(dp), allocatable :: impulse(:)   !! (2m) r = (p_1, r_T1, p_2, r_T2, ...), N s
      real(dp), allocatable :: velocity(:)  !! (2m) u = D r + q, m/s
      integer, allocatable :: state(:)      !! (m) contact_separating, _sticking or _slipping
      integer :: pivots = 0                 !! Lemke pivots
      integer :: lcp_size = 0               !! unknowns of the LCP: m + 3 (contacts with mu > 0)
      real(dp) :: residual = 0.0_dp         !! coulomb_residual of the result
   end type frictional_contact_solution

contains

   !> Solve the 2-D frictional contact problem (module documentation) by Lemke's method on
   !! Stewart & Trinkle's LCP. m = 0 returns empty arrays.
   !!
   !! Status codes (vibrobeam_status; `errmsg` empty when stat = 0):
   !! * stat_ok: the Coulomb conditions hold with `coulomb_residual` <= tolerance.
   !! * stat_invalid_argument: inconsistent sizes, mu < 0, a non-finite entry.
   !! * those of `solve_lemke` (ray, pivot limit, singular basis, check), passed on with
   !!   its message: D is then not positive semidefinite or q violates the condition above.
   !! * stat_residual_check_failed: the LCP solution violates the Coulomb conditions by
   !!   more than the tolerance (round-off; D too ill-conditioned).
   subroutine solve_frictional_contact(delassus, free_velocity, friction, solution, stat, errmsg, tolerance)
      real(dp), intent(in) :: delassus(:, :)     !! (2m, 2m) D = H W^-1 H^T, symmetric PSD, m/(N s)
      real(dp), intent(in) :: free_velocity(:)   !! (2m) q, m/s, (normal, tangent) per contact
      real(dp), intent(in) :: friction(:)        !! (m) friction coefficients mu >= 0
      type(frictional_contact_solution), intent(out) :: solution
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      !> Relative tolerance of the final check, default 1e-10 (see `coulomb_residual`).
      real(dp), intent(in), optional :: tolerance

      real(dp), allocatable :: lcp_matrix(:, :), lcp_vector(:), z(:), w(:)
      logical, allocatable :: basic(:)
      integer, allocatable :: rough(:)   ! the contacts with mu > 0
      integer :: m, f, i, k
      real(dp) :: check_tolerance, speed_scale
      character(len=buffer_length) :: message

      stat = 0
      errmsg = ''
      m = size(friction)
      allocate (solution%impulse(2*m), solution%velocity(2*m), source=0.0_dp)
      allocate (solution%state(m), source=contact_separating)
      check_tolerance = default_tolerance
      if (present(tolerance)) check_tolerance = tolerance
      if (size(delassus, 1) /= 2*m .or. size(delassus, 2) /= 2*m .or. size(free_velocity) /= 2*m) then
         write (message, '(a, 4(i0, a))') 'solve_frictional_contact: inconsistent sizes: delassus is ', &
            size(delassus, 1), ' x ', size(delassus, 2), ', free_velocity has ', size(free_velocity), &
            ' entries, friction ', m, ' (expected 2m x 2m, 2m, m).'
         call fail(stat_invalid_argument, message, stat, errmsg)
         return
      end if
      if (.not. (all(ieee_is_finite(delassus)) .and. all(ieee_is_finite(free_velocity)) .and. &
                 all(ieee_is_finite(friction)))) then
         call fail(stat_invalid_argument, 'solve_frictional_contact: delassus, free_velocity or friction '// &
                   'has a NaN or infinite entry.', stat, errmsg)
         return
      end if
      if (any(friction < 0.0_dp)) then
         write (message, '(a, es10.3, a)') 'solve_frictional_contact: friction coefficient ', minval(friction), &
            ' is negative; mu >= 0 is allowed.'
         call fail(stat_invalid_argument, message, stat, errmsg)
         return
      end if
      if (.not. (check_tolerance > 0.0_dp .and. ieee_is_finite(check_tolerance))) then
         call fail(stat_invalid_argument, 'solve_frictional_contact: tolerance is not a positive finite number.', &
                   stat, errmsg)
         return
      end if
      if (m == 0) return

      rough = pack([(i, i=1, m)], friction > 0.0_dp)
      f = size(rough)
      solution%lcp_size = m + 3*f
      ! lambda is carried as lambda/s and its complementary row multiplied by s, with s the
      ! largest |D_ij|, so that every entry of the LCP matrix is in D's units (m/(N s)):
      ! Lemke's tolerances then compare like with like. A positive diagonal scaling changes
      ! neither the solutions nor copositivity.
      speed_scale = max(maxval(abs(delassus)), tiny(1.0_dp))
      call stewart_trinkle_lcp(delassus, free_velocity, friction, rough, speed_scale, lcp_matrix, lcp_vector)
      allocate (z(m + 3*f), w(m + 3*f), basic(m + 3*f))
      call solve_lemke(lcp_matrix, lcp_vector, z, w, solution%pivots, stat, errmsg, tolerance=check_tolerance, &
                       basic=basic)
      if (stat /= 0) return

      solution%impulse(1:2*m:2) = z(1:m)
      do k = 1, f
         solution%impulse(2*rough(k)) = z(m + k) - z(m + f + k)
      end do
      solution%velocity = matmul(delassus, solution%impulse) + free_velocity
      ! States from the final basis: p basic and positive closes a contact; a basic, positive
      ! sliding speed lambda makes it slip.
      where (z(1:m) > 0.0_dp) solution%state = contact_sticking
      where (z(1:m) > 0.0_dp .and. .not. friction > 0.0_dp) solution%state = contact_slipping
      do k = 1, f
         if (basic(m + 2*f + k) .and. z(m + 2*f + k) > 0.0_dp .and. z(rough(k)) > 0.0_dp) &
            solution%state(rough(k)) = contact_slipping
      end do

      solution%residual = coulomb_residual(delassus, free_velocity, friction, solution%impulse)
      if (solution%residual > check_tolerance) then
         write (message, '(a, es10.3, a, es10.3, a, i0, a)') 'solve_frictional_contact: the Coulomb residual ', &
            solution%residual, ' of the result exceeds the tolerance ', check_tolerance, ' (m = ', m, &
            ' contacts; D may be too ill-conditioned).'
         call fail(stat_residual_check_failed, message, stat, errmsg)
      end if
   end subroutine solve_frictional_contact

   !> Stewart & Trinkle's LCP (module documentation) for the contacts `rough` (mu > 0),
   !! unknowns z = (p(1:m), beta+(1:f), beta-(1:f), lambda(1:f)/s):
   !!
   !!     M = [  D_NN   D_NT  -D_NT   0  ]      q = [  q_N ]
   !!         [  D_TN   D_TT  -D_TT   sI ]          [  q_T ]
   !!         [ -D_TN  -D_TT   D_TT   sI ]          [ -q_T ]
   !!         [ s mu E  -sI    -sI    0  ]          [  0   ]
   !!
   !! (T: the tangents of the rough contacts, E: their rows of the identity on p).
   pure subroutine stewart_trinkle_lcp(delassus, free_velocity, friction, rough, s, lcp_matrix, lcp_vector)
      real(dp), intent(in) :: delassus(:, :), free_velocity(:), friction(:), s
      integer, intent(in) :: rough(:)
      real(dp), allocatable, intent(out) :: lcp_matrix(:, :), lcp_vector(:)
      integer :: m, f, i, j, k, l
      m = size(friction)
      f = size(rough)
      allocate (lcp_matrix(m + 3*f, m + 3*f), lcp_vector(m + 3*f), source=0.0_dp)
      ! Normal rows and columns: p at i, the normal of contact i at 2i - 1.
      do j = 1, m
         do i = 1, m
            lcp_matrix(i, j) = delassus(2*i - 1, 2*j - 1)
         end do
         lcp_vector(j) = free_velocity(2*j - 1)
      end do
      ! Tangential blocks: beta+ at m + k, beta- at m + f + k for the tangent 2 rough(k).
      do l = 1, f
         do i = 1, m
            lcp_matrix(i, m + l) = delassus(2*i - 1, 2*rough(l))
            lcp_matrix(i, m + f + l) = -delassus(2*i - 1, 2*rough(l))
            lcp_matrix(m + l, i) = delassus(2*rough(l), 2*i - 1)
            lcp_matrix(m + f + l, i) = -delassus(2*rough(l), 2*i - 1)
         end do
         do k = 1, f
            lcp_matrix(m + k, m + l) = delassus(2*rough(k), 2*rough(l))
            lcp_matrix(m + k, m + f + l) = -delassus(2*rough(k), 2*rough(l))
            lcp_matrix(m + f + k, m + l) = -delassus(2*rough(k), 2*rough(l))
            lcp_matrix(m + f + k, m + f + l) = delassus(2*rough(k), 2*rough(l))
         end do
      end do
      ! The sliding speed lambda/s at m + 2f + k and the cone's row.
      do k = 1, f
         lcp_matrix(m + k, m + 2*f + k) = s
         lcp_matrix(m + f + k, m + 2*f + k) = s
         lcp_matrix(m + 2*f + k, rough(k)) = s*friction(rough(k))
         lcp_matrix(m + 2*f + k, m + k) = -s
         lcp_matrix(m + 2*f + k, m + f + k) = -s
         lcp_vector(m + k) = free_velocity(2*rough(k))
         lcp_vector(m + f + k) = -free_velocity(2*rough(k))
      end do
   end subroutine stewart_trinkle_lcp

   !> Largest violation of the Coulomb conditions by the impulse r, with u = D r + q
   !! recomputed, all in velocity units (|D| = max_ij |D_ij| converts impulses) and divided
   !! by the velocity scale max(|q|_inf, |D| |r|_inf). Per contact:
   !!
   !! * Signorini: max(-|D| p, -u_N, min(|D| p+, u_N+));
   !! * the cone: |D| (|r_T| - mu p)+;
   !! * stick or slip: min(|u_T|, |D| (mu p - |r_T|)) (u_T = 0, or r_T on the cone's edge);
   !! * slip opposes motion: min(|u_T|, |D| |r_T|) when r_T u_T > 0.
   !!
   !! Zero exactly when r solves the problem. Sizes are not checked (2m x 2m, 2m, m, 2m).
   pure function coulomb_residual(delassus, free_velocity, friction, impulse) result(residual)
      real(dp), intent(in) :: delassus(:, :)    !! (2m, 2m) D
      real(dp), intent(in) :: free_velocity(:)  !! (2m) q
      real(dp), intent(in) :: friction(:)       !! (m) mu
      real(dp), intent(in) :: impulse(:)        !! (2m) r, the candidate solution
      real(dp) :: residual                      !! normalized largest violation
      real(dp) :: velocity(size(impulse)), d_norm, scale, p, r_t, u_n, u_t, violation
      integer :: i
      residual = 0.0_dp
      if (size(friction) == 0) return
      velocity = matmul(delassus, impulse) + free_velocity
      d_norm = maxval(abs(delassus))
      scale = max(maxval(abs(free_velocity)), d_norm*maxval(abs(impulse)), tiny(1.0_dp))
      violation = 0.0_dp
      do i = 1, size(friction)
         p = impulse(2*i - 1)
         r_t = impulse(2*i)
         u_n = velocity(2*i - 1)
         u_t = velocity(2*i)
         violation = max(violation, -d_norm*p, -u_n, min(d_norm*max(p, 0.0_dp), max(u_n, 0.0_dp)), &
                         d_norm*(abs(r_t) - friction(i)*p), &
                         min(abs(u_t), d_norm*(friction(i)*p - abs(r_t))))
         if (r_t*u_t > 0.0_dp) violation = max(violation, min(abs(u_t), d_norm*abs(r_t)))
      end do
      residual = violation/scale
   end function coulomb_residual


end module vibrobeam_frictional_contact
