!> Static lift-off scenes against their closed forms (issue 10; docs/theory.md §7 "Exact
!! references"): a clamped Hermite beam on a rigid floor w >= 0 under its whole length,
!! uniform load q < 0, and a force F > 0 lifting either the tip or the mid-span.
!!
!! Continuum. In the contact zone w = 0, so the moment and the shear vanish there and the
!! floor carries |q| per unit length; at touchdown it adds a concentrated reaction.
!! - tip: the lifted end is a cantilever of length a clamped at touchdown with zero root
!!   moment, F a - |q| a^2/2 = 0: a = 2F/|q|; w(s) = F s^3 (2a - s)/(12 a EI) (s from
!!   touchdown), tip w = F a^3/(12 EI) = (2/3) F^4/(|q|^3 EI); touchdown reaction F.
!! - mid-span: by symmetry each half of the lifted zone (half-width b) has w = w' = w'' = 0
!!   at touchdown, w' = 0 and shear -F/2 at the centre: b = 3F/(4|q|), w(s) =
!!   |q| s^3 (4b - 3s)/(72 EI), centre w = |q| b^4/(72 EI); touchdown reactions F/4 each.
!! Either way the reactions sum to |q| L - F.
!!
!! Discrete (what Hermite elements with the consistent load vector give exactly). The
!! constraints act at the nodes only: in the contact zone w_i = 0 while the rotations are
!! free, so the zone is a continuous beam on point supports, whose elements carry the
!! fixed-end moment |q| h^2/12. Its rotational equations 2 th_{i-1} + 8 th_i + 2 th_{i+1}
!! = 0 give th_{i-k} = th_t r^k, r = sqrt(3) - 2, and a rotational stiffness
!! k_c = 2 sqrt(3) EI/h at the touchdown node. Hermite elements are nodally exact for a
!! beam segment (any load, consistent load vector), so with touchdown at node j
!! (lifted length a_d) the exact discrete solution is: w = 0 in the zone; on the lifted
!! segment w = w_c(s) + w_rot(s), w_c the segment clamped at touchdown, w_rot the motion
!! of a touchdown rotation th_t (tip: the rigid rotation th_t s; mid-span: th_t s (l - s)/l,
!! l = 2 b_d, which bends the segment with root stiffness EI/b_d), and the moment balance
!! at touchdown (k_c + k_lift) th_t = |q| h^2/12 + M_c, M_c = EI w_c''(0) (tip: F a_d -
!! |q| a_d^2/2; mid-span: F b_d/4 - |q| b_d^2/3). Reactions: zone node i, |q| h +
!! (6 EI/h^2)(th_{i+1} - th_{i-1}); touchdown, |q| h/2 + (root shear of the lifted
!! segment: |q| a_d - F, resp. |q| b_d - F/2) - (6 EI/h^2)(1 + r) th_t; lifted nodes 0;
!! their sum is |q|(L - h/2) - F (the clamp takes |q| h/2 of the first element). The
!! rotations decay like r^k away from touchdown, so the clamp (and for the mid-span scene
!! the free end, which carries an unbalanced |q| h^2/12 of its own) changes nothing above
!! r^40 < 1e-22 when they are 40 elements away, as here. When a/h (b/h) is an integer,
!! M_c = 0 and the discrete lifted length is the continuum one; the discrete tip (centre)
!! deflection then differs from the continuum by th_t a (th_t b/2): relative
!! (h/a)^3/sqrt(3) (tip), about (sqrt(3)/2)(h/b)^3 (mid-span).
!!
!! Checks at each N (touchdown found by testing every candidate node against the
!! optimality conditions of the formula above: exactly one must satisfy them):
!! 1. the solver's lifted nodes are the reference's, and the lifted length is within one
!!    element of the continuum a (2b);
!! 2. no node with a gap above the round-off bound delta_w carries a reaction (exactly 0:
!!    the active-set finish), and no reaction is negative;
!! 3. w and R against the discrete reference within the derived round-off bounds of the
!!    solver (`static_report`: unknown_bound, reaction_bound; derivation in
!!    src/model/vibrobeam_support_moments.f90 and src/analysis/vibrobeam_static.f90), plus
!!    16 eps of the reference's own terms;
!! 4. tip (centre) deflection against the continuum closed form, after the discrete
!!    difference th_t a (th_t b/2) derived above, to the round-off bound;
!! 5. sum of reactions against |q|(L - h/2) - F (the translation rows of K sum to the
!!    clamp's term -(6 EI/h^2) th_1 alone) to the solver's bound of the sum, the rounding
!!    of the sum and (6 EI/h^2) |th_1|, and against the continuum |q| L - F to |q| h/2 + that.
!!
!! usage: test_liftoff_closed_form SCENE.nml tip|mid N...
program test_liftoff_closed_form
   use vibrobeam_kinds, only: dp, output_unit
   use vibrobeam_scene, only: scene_type
   use vibrobeam_problem, only: run_problem
   use vibrobeam_static, only: solve_static, static_report
   use vibrobeam_test_support, only: test_counter, read_test_scene, prepare_test_scene
   implicit none

   type(test_counter) :: t
   type(scene_type) :: scene
   character(len=512) :: path, kind, argument
   integer :: i, elements
   real(dp), parameter :: r = sqrt(3.0_dp) - 2

   call get_command_argument(1, path)
   call get_command_argument(2, kind)
   if (kind /= 'tip' .and. kind /= 'mid') error stop 'usage: test_liftoff_closed_form SCENE.nml tip|mid N...'
   scene = read_test_scene(trim(path))
   do i = 3, command_argument_count()
      call get_command_argument(i, argument)
      read (argument, *) elements
      scene%mesh%elements = elements
      call check_scene(scene)
   end do
   call t%finish('test_liftoff_closed_form')

contains

   real(dp) pure function rounding_gamma(n)
      integer, intent(in) :: n
      rounding_gamma = n*epsilon(1.0_dp)/(1 - n*epsilon(1.0_dp))
   end function rounding_gamma

   !> The exact discrete solution for lifted half-length m elements (tip: the lifted
   !! length; mid-span: the half-width), or ok = .false. if it violates the optimality
   !! conditions (a lifted node below the floor or a negative reaction).
   subroutine discrete_solution(n, h, q, f, ei, m, u, reaction, theta_t, ok)
      integer, intent(in) :: n, m
      real(dp), intent(in) :: h, q, f, ei   !! q = |load| > 0
      real(dp), intent(out) :: u(:), reaction(:), theta_t
      logical, intent(out) :: ok
      real(dp) :: ad, s, ell, m_c, k_lift, w, th, root_shear, theta_end
      integer :: j, k, centre, touch(2), side, first, last
      u = 0
      reaction = 0
      ad = m*h
      ell = 2*ad
      if (kind == 'tip') then
         m_c = f*ad - q*ad**2/2
         k_lift = 0
         root_shear = q*ad - f
         touch = [n - m, 0]
         first = n - m + 1
         last = n
      else
         ell = 2*ad
         m_c = f*ad/4 - q*ad**2/3
         k_lift = ei/ad
         root_shear = q*ad - f/2
         centre = n/2
         touch = [centre - m, centre + m]
         first = centre - m + 1
         last = centre + m - 1
      end if
      theta_t = (q*h**2/12 + m_c)/(2*sqrt(3.0_dp)*ei/h + k_lift)
      ! lifted segment (s from the left touchdown node)
      do j = first, last
         s = (j - touch(1))*h
         if (kind == 'tip') then
            w = (f*s**2*(3*ad - s)/6 - q*s**2*(6*ad**2 - 4*ad*s + s**2)/24)/ei + theta_t*s
            th = (f*s*(2*ad - s)/2 - q*s*(3*ad**2 - 3*ad*s + s**2)/6)/ei + theta_t
         else
            ! clamped-clamped segment of length ell, uniform -q and F up at the centre,
            ! symmetric about s = ad
            if (s > ad) s = ell - s
            w = (-q*s**2*(ell - s)**2/24 + f*s**2*(3*ell - 4*s)/48)/ei + theta_t*s*(ell - s)/ell
            th = (-q*s*(ell - s)*(ell - 2*s)/12 + f*s*(ell - 2*s)/8)/ei + theta_t*(ell - 2*s)/ell
            if ((j - touch(1))*h > ad) th = -th
         end if
         u(2*j - 1) = w
         u(2*j) = th
      end do
      ! zone rotations, decaying away from each touchdown node
      do side = 1, merge(1, 2, kind == 'tip')
         do k = 0, n
            j = touch(side) + merge(-k, k, side == 1)
            if (j < 1 .or. j > n) exit
            u(2*j) = merge(1, -1, side == 1)*theta_t*r**k
         end do
      end do
      ! mid-span: the free end is held too, and its element's unbalanced fixed-end moment
      ! q h^2/12 turns it like a touchdown node with nothing lifted beyond
      theta_end = 0
      if (kind == 'mid') then
         theta_end = (q*h**2/12)/(2*sqrt(3.0_dp)*ei/h)
         do k = 0, n - touch(2) - 1
            u(2*(n - k)) = u(2*(n - k)) + theta_end*r**k
         end do
      end if
      ! reactions
      do j = 1, n
         if (j >= first .and. j <= last) cycle
         if (kind == 'mid' .and. j == n) then
            reaction(j) = q*h/2 - 6*ei/h**2*(rotation(u, n, n - 1) + rotation(u, n, n))
         else if (any(j == touch)) then
            reaction(j) = q*h/2 + root_shear - 6*ei/h**2*(1 + r)*abs(theta_t)
         else
            reaction(j) = q*h + 6*ei/h**2*(rotation(u, n, j + 1) - rotation(u, n, j - 1))
         end if
      end do
      ok = all(reaction >= 0) .and. all(u(2*first - 1:2*last - 1:2) > 0)
   end subroutine discrete_solution

   !> theta at `node` (0 beyond the beam: the clamp, or past the free end).
   pure real(dp) function rotation(u, n, node)
      real(dp), intent(in) :: u(:)
      integer, intent(in) :: n, node
      rotation = 0
      if (node >= 1 .and. node <= n) rotation = u(2*node)
   end function rotation

   subroutine check_scene(scene)
      type(scene_type), intent(in) :: scene
      type(run_problem) :: prepared
      real(dp), allocatable :: u(:), reaction(:), force(:), u_ref(:), r_ref(:), bound_u(:), bound_r(:), &
                               trial_u(:), trial_r(:)
      real(dp) :: h, q, f, ei, a, length, delta_w, theta_t, trial_theta, continuum, predicted, deflection, sum_bound
      integer :: n, j, m, m_ref, stat, iterations, found, lifted, solver_lifted, first_diff, probe, window
      type(static_report) :: report
      logical :: ok
      character(len=512) :: errmsg
      character(len=200) :: detail, label
      call prepare_test_scene(scene, prepared)
      n = scene%mesh%elements
      length = prepared%model%length
      h = length/n
      q = -scene%load%distributed
      f = scene%load%point_force
      ei = prepared%model%ei
      if (q <= 0 .or. f <= 0 .or. prepared%contacts%count /= n) error stop 'test_liftoff_closed_form: scene shape'
      force = prepared%loads%at(0.0_dp)
      allocate (u(2*n), reaction(n), u_ref(2*n), r_ref(n), trial_u(2*n), trial_r(n))
      call solve_static(prepared%model, prepared%contacts, force, u, reaction, iterations, stat, errmsg, report=report)
      write (label, '(a,a,i0)') trim(kind), ' N = ', n
      call t%check_true(trim(label)//': solve_static succeeds', stat == 0, trim(errmsg))
      ! continuum lifted length (tip) or half-width (mid-span)
      a = merge(2*f/q, 3*f/(4*q), kind == 'tip')
      ! the touchdown: the candidate that satisfies the optimality conditions (the solution
      ! is unique, K being positive definite; searched within 20 elements of the continuum
      ! touchdown, keeping it 40 elements from the ends)
      found = 0
      m_ref = 0
      theta_t = 0
      window = nint(a/h)
      do m = max(1, window - 20), min(window + 20, merge(n - 40, n/2 - 40, kind == 'tip'))
         call discrete_solution(n, h, q, f, ei, m, trial_u, trial_r, trial_theta, ok)
         if (.not. ok) cycle
         found = found + 1
         m_ref = m
         u_ref = trial_u
         r_ref = trial_r
         theta_t = trial_theta
      end do
      write (detail, '(a,i0)') 'candidates that satisfy the optimality conditions: ', found
      call t%check_true(trim(label)//': exactly one discrete touchdown', found == 1, trim(detail))
      if (found /= 1) return
      ! round-off bounds (module comment, item 3)
      ! round-off bounds (module comment, item 3): the solver's derived bounds of each
      ! unknown and each reaction, plus the reference's own rounding
      allocate (bound_u(2*n), bound_r(n))
      bound_u = report%unknown_bound + 16*epsilon(1.0_dp)*abs(u_ref)
      delta_w = maxval(report%unknown_bound(1::2))
      bound_r = report%reaction_bound + 16*epsilon(1.0_dp)*(q*h + f + 12*ei/h**2*maxval(abs(u_ref(2::2))))
      ! 1. the lifted set
      lifted = count(.not. abs(r_ref) > 0)
      solver_lifted = count(.not. abs(reaction) > 0)
      first_diff = 0
      do j = 1, n
         if ((.not. abs(reaction(j)) > 0) .neqv. (.not. abs(r_ref(j)) > 0)) then
            first_diff = j
            exit
         end if
      end do
      write (detail, '(a,i0,a,i0,a,i0)') 'lifted nodes ', solver_lifted, ', reference ', lifted, &
         ', first difference at node ', first_diff
      call t%check_true(trim(label)//': lifted nodes are those of the discrete reference', first_diff == 0, trim(detail))
      write (detail, '(a,es12.5,a,es12.5,a,es10.3)') 'lifted length ', merge(1, 2, kind == 'tip')*m_ref*h, &
         ', continuum ', merge(1, 2, kind == 'tip')*a, ', h ', h
      call t%check_true(trim(label)//': lifted length within one element of the continuum', &
                        abs(m_ref*h - a) <= h, trim(detail))
      ! 2. no reaction on a lifted node, none negative
      probe = 0
      do j = 1, n
         if (u(2*j - 1) > delta_w .and. abs(reaction(j)) > 0) probe = probe + 1
      end do
      write (detail, '(i0,a,es10.3)') probe, ' nodes with a reaction and a gap above delta_w = ', delta_w
      call t%check_true(trim(label)//': no reaction where the gap exceeds its round-off bound', probe == 0, trim(detail))
      call t%check_true(trim(label)//': no negative reaction', all(reaction >= 0))
      ! 3. against the discrete reference
      write (detail, '(a,es10.3,a,es10.3)') 'largest |w - w_ref| ', maxval(abs(u(1::2) - u_ref(1::2))), &
         ', delta_w ', delta_w
      call t%check_true(trim(label)//': displacements equal the discrete closed form to the round-off bound', &
                        all(abs(u - u_ref) <= bound_u), trim(detail))
      write (detail, '(a,es10.3,a,es10.3)') 'largest |R - R_ref|/bound ', maxval(abs(reaction - r_ref)/bound_r)
      call t%check_true(trim(label)//': reactions equal the discrete closed form to the round-off bound', &
                        all(abs(reaction - r_ref) <= bound_r), trim(detail))
      ! 4. tip / centre deflection against the continuum
      if (kind == 'tip') then
         continuum = 2*f**4/(3*q**3*ei)
         deflection = u(2*n - 1)
         predicted = theta_t*m_ref*h + ((f*(m_ref*h)**3/3 - q*(m_ref*h)**4/8)/ei - continuum)
      else
         continuum = q*a**4/(72*ei)
         deflection = u(n - 1)
         predicted = theta_t*m_ref*h/2 + ((f*(m_ref*h)**3 - q*(m_ref*h)**4)/(24*ei) - continuum)
      end if
      write (output_unit, '(a,i0,a,i0,a,es12.5,a,es12.5,a,es10.3,a,es10.3,a,es10.3)') trim(kind)//' N = ', n, &
         ': lifted nodes ', solver_lifted, ', lifted length ', merge(1, 2, kind == 'tip')*m_ref*h, ' (continuum ', &
         merge(1, 2, kind == 'tip')*a, '); deflection error vs continuum ', deflection/continuum - 1, &
         ' (derived ', predicted/continuum, '); delta_w ', delta_w
      if (abs(m_ref*h - a) <= 1e-12_dp*a) then   ! a/h integer: M_c = 0 and the difference is th_t a (th_t b/2)
         call t%check_true(trim(label)//': deflection minus its derived discretization difference equals the '// &
                           'continuum closed form', abs(deflection - continuum - predicted) <= &
                           delta_w + 64*epsilon(1.0_dp)*continuum, '')
      end if
      ! 5. sum of reactions
      ! the translation rows of K sum to the clamp's share of element 1 only (every other
      ! element's rows sum to 0): sum R = |q|(L - h/2) - F - (6 EI/h^2) th_1, to the bound of
      ! each reaction and the rounding of the sum
      sum_bound = rounding_gamma(n)*sum(abs(reaction)) + report%reaction_sum_bound + &
                  6*ei/h**2*(abs(u_ref(2)) + bound_u(2))
      write (output_unit, '(a,es22.15,a,es22.15,a,es10.3,a,es10.3)') '  sum of reactions ', sum(reaction), &
         ', discrete |q|(L - h/2) - F = ', q*(length - h/2) - f, ', bound ', sum_bound, '; continuum |q| L - F = ', &
         q*length - f
      call t%check_true(trim(label)//': sum of reactions = |q|(L - h/2) - F', &
                        abs(sum(reaction) - (q*(length - h/2) - f)) <= sum_bound)
      call t%check_true(trim(label)//': sum of reactions = |q| L - F to |q| h/2', &
                        abs(sum(reaction) - (q*length - f)) <= q*h/2 + sum_bound)
   end subroutine check_scene
end program test_liftoff_closed_form
