!> Which degrees of freedom of the mesh's basis are unknowns, which the supports hold, and
!! which the supports tie to others (docs/method.md, "Supports"; theory §2).
!!
!! Hermite elements (w_i, theta_i at node i = 0..N): every support holds whole degrees of
!! freedom: a held deflection removes w_i, a held rotation theta_i.
!!
!! Cubic B-splines (c_1..c_{N+3}): u(0) = c_1, u'(0) = 3 (c_2 - c_1)/h and symmetrically at
!! L, so a held end deflection removes c_1 (c_{N+3}) and a clamp also c_2 (c_{N+2}); a
!! sliding end (u' = 0, u free) is c_2 = c_1, a change of basis: the two coefficients
!! become one unknown whose function is B_1 + B_2. At an interior node x_i three
!! functions are nonzero, B_{i+1}, B_{i+2}, B_{i+3} with values w_1, w_2, w_3 (1/6, 2/3, 1/6
!! away from the ends): a pinned support (u(x_i) = 0) sets
!! c_{i+2} = -(w_1 c_{i+1} + w_3 c_{i+3})/w_2. A clamped interior support is refused: its
!! reaction moment bends u'' at the node, which a C^2 spline cannot (`build_model` refuses
!! every point moment inside a B-spline beam; Hermite elements are only C^1 and take it).
!! Each such coefficient is a combination of at most two unknowns ("terms"); the elements
!! keep at most four unknowns and the band its three sub-diagonals as long as no
!! coefficient takes part in two constraints: B-spline supports must be at least three
!! elements apart and not next to a clamped or sliding end (checked; Hermite elements have
!! no such limit).
module vibrobeam_dof_map
   use vibrobeam_kinds, only: dp
   use vibrobeam_bspline, only: bspline_shape
   use vibrobeam_boundary, only: end_sliding
   use vibrobeam_structure, only: beam_structure, support_pinned, support_clamped
   implicit none
   private
   public :: dof_map, build_dof_map

   !> The map from degrees of freedom of the basis to unknowns.
   type :: dof_map
      integer :: unknowns = 0                   !! J
      logical :: combined = .false.             !! some degree of freedom is a combination
      !> (ndof) unknown of each degree of freedom; 0: held (zero); -1: a combination (terms)
      integer, allocatable :: unknown_of(:)
      integer, allocatable :: term_unknown(:,:)    !! (2, ndof) unknowns of a combination (0: none)
      real(dp), allocatable :: term_weight(:,:)    !! (2, ndof) their weights
      logical, allocatable :: deflection_held(:)   !! (0:N) u(x_i) = 0 by a support
   end type dof_map

contains

   !> The map of `structure`'s supports on a mesh of `elements` elements of the basis
   !! (`hermite`, else B-splines on `knots`). stat = 1 with a message when two B-spline
   !! supports share a coefficient (module documentation).
   subroutine build_dof_map(hermite, elements, knots, structure, support_node, map, stat, errmsg)
      logical, intent(in) :: hermite
      integer, intent(in) :: elements
      real(dp), intent(in) :: knots(:)            !! B-splines: the N + 7 knots (else unused)
      type(beam_structure), intent(in) :: structure
      integer, intent(in) :: support_node(:)      !! the node (1..N-1) of each intermediate support
      type(dof_map), intent(out) :: map
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer, allocatable :: state(:), target_dof(:,:)
      logical, allocatable :: touched(:)
      real(dp) :: values(4), w(3)
      integer :: n, k, s, node, i, a
      ! state: 0 free, 1 held, 2 a combination of the free degrees of freedom target_dof
      stat = 0
      errmsg = ''
      n = merge(2*(elements + 1), elements + 3, hermite)
      allocate (state(n), source=0)
      allocate (target_dof(2, n), source=0)
      allocate (map%term_weight(2, n), source=0.0_dp)
      allocate (touched(n), source=.false.)
      allocate (map%deflection_held(0:elements), source=.false.)
      associate (b => structure%boundary)
         map%deflection_held(0) = b%holds_deflection(1)
         map%deflection_held(elements) = b%holds_deflection(2)
         if (hermite) then
            if (b%holds_deflection(1)) state(1) = 1
            if (b%holds_rotation(1)) state(2) = 1
            if (b%holds_deflection(2)) state(n - 1) = 1
            if (b%holds_rotation(2)) state(n) = 1
         else
            call end_coefficients(1, 2, b%left, b%holds_deflection(1), b%holds_rotation(1))
            call end_coefficients(n, n - 1, b%right, b%holds_deflection(2), b%holds_rotation(2))
         end if
      end associate
      do s = 1, structure%supports()
         node = support_node(s)
         if (structure%support_kind(s) /= support_pinned .and. structure%support_kind(s) /= support_clamped) cycle
         map%deflection_held(node) = .true.
         if (hermite) then
            state(2*node + 1) = 1
            if (structure%support_kind(s) == support_clamped) state(2*node + 2) = 1
            cycle
         end if
         ! the three coefficients nonzero at x_node: B_(node+1..node+3), from element `node`
         if (any(touched(node + 1:node + 3))) then
            stat = 1
            write (errmsg, '(a,i0,a,i0,a)') '&supports x(', s, '): its node ', node, ' shares a B-spline coefficient '// &
               'with another support or a clamped or sliding end: with &mesh basis = ''bspline'' supports must be at '// &
               'least 3 elements apart and 2 from a clamped or sliding end (or use basis = ''hermite'')'
            return
         end if
         touched(node + 1:node + 3) = .true.
         if (structure%support_kind(s) == support_clamped) then
            stat = 1
            write (errmsg, '(a,i0,a)') '&supports kind(', s, ') = ''clamped'': a clamped support inside the beam '// &
               'bends u'''' at its node, which &mesh basis = ''bspline'' (C^2 splines) cannot; use basis = ''hermite'''
            return
         end if
         values = bspline_shape(knots, node, knots(node + 4), 0)
         w = values(2:4)
         state(node + 2) = 2
         call add_term(node + 2, node + 1, -w(1)/w(2))
         call add_term(node + 2, node + 3, -w(3)/w(2))
      end do
      ! number the free degrees of freedom, then point the combinations at their unknowns
      allocate (map%unknown_of(n), source=0)
      allocate (map%term_unknown(2, n), source=0)
      do k = 1, n
         if (state(k) /= 0) cycle
         map%unknowns = map%unknowns + 1
         map%unknown_of(k) = map%unknowns
      end do
      do k = 1, n
         if (state(k) /= 2) cycle
         map%combined = .true.
         map%unknown_of(k) = -1
         do a = 1, 2
            i = target_dof(a, k)
            if (i == 0) cycle
            if (state(i) == 0) map%term_unknown(a, k) = map%unknown_of(i)
            ! a held target (a support next to a pinned end) contributes nothing
            if (state(i) /= 0) map%term_weight(a, k) = 0
         end do
      end do

   contains

      !> The B-spline coefficients of an end: `outer` (c_1 or c_{N+3}) and `inner` (c_2 or c_{N+2}).
      subroutine end_coefficients(outer, inner, support, deflection, rotation)
         integer, intent(in) :: outer, inner, support
         logical, intent(in) :: deflection, rotation
         if (deflection) state(outer) = 1
         if (rotation .and. deflection) state(inner) = 1
         if (support == end_sliding) then
            state(inner) = 2
            call add_term(inner, outer, 1.0_dp)
         end if
         if (rotation) touched([outer, inner]) = .true.
      end subroutine end_coefficients

      !> Degree of freedom k takes `weight` times degree of freedom `target`.
      subroutine add_term(k, target, weight)
         integer, intent(in) :: k, target
         real(dp), intent(in) :: weight
         integer :: slot
         slot = merge(1, 2, target_dof(1, k) == 0)
         target_dof(slot, k) = target
         map%term_weight(slot, k) = weight
      end subroutine add_term
   end subroutine build_dof_map
end module vibrobeam_dof_map
