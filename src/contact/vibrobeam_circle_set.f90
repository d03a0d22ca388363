!> The contact points of the obstacles in the cross-section of a beam bending in two
!! planes (docs/method.md, "Circular obstacles"): at point k, node `node(k)`, the beam's
!! deflection (v, w) must stay inside the circle of radius `radius(k)` about
!! `center(:, k)`, R - |(v, w) - c| >= 0, or, a flat point (a level obstacle of a beam of
!! two planes), on the allowed side of a line, h.(v, w) - b >= 0 with the fixed inward
!! unit normal h = `normal(:, k)` ((1, 0) for a level below, (-1, 0) above) and b =
!! `bound(k)`. With the state stacked y then z (J unknowns per plane) the point's
!! deflections are the unknowns dof(k) and J + dof(k). Which obstacles give which points
!! is `vibrobeam_obstacles`' job (`build_circle_points`).
module vibrobeam_circle_set
   use vibrobeam_kinds, only: dp
   implicit none
   private
   public :: circle_set

   type :: circle_set
      integer :: count = 0
      integer, allocatable :: node(:)          !! node index i (1..N), x_k = x_i
      real(dp), allocatable :: x(:)            !! position along the beam (m)
      integer, allocatable :: dof(:)           !! the unknown of the deflection in y at the node
      real(dp), allocatable :: radius(:)       !! R (m) of a circle
      real(dp), allocatable :: center(:, :)    !! (2, count) c = (c_y, c_z) (m) of a circle
      logical, allocatable :: flat(:)          !! a flat point (a level), not a circle
      real(dp), allocatable :: normal(:, :)    !! (2, count) a flat point's inward unit normal h
      real(dp), allocatable :: bound(:)        !! a flat point's b (m): h.(v, w) >= b
      integer, allocatable :: obstacle(:)      !! the obstacle (index in &obstacles)
      !> compliant points (docs/theory.md section 8 on the penetration `penetration`: the
      !! radial |r - c| - R of a circle, b - h.(v, w) of a flat point): stiffness k (N/m^a
      !! at the point; 0: rigid), exponent a, Hunt-Crossley alpha
      real(dp), allocatable :: stiffness(:), exponent(:), damping(:)
      logical :: compliant = .false.           !! every point compliant (none rigid)
      real(dp), allocatable :: friction(:)     !! Coulomb's mu at the point's wall (0: frictionless)
   contains
      procedure :: position                    !! (v, w) of point k in a stacked state
      procedure :: offset                      !! r - c of point k in a stacked state
      procedure :: gap_at                      !! the distance to the wall of a position (m)
      procedure :: normal_at                   !! the inward unit normal there
      procedure :: penetration                 !! how far point k is beyond its wall (m)
      procedure :: frictional                  !! has any point friction?
   end type circle_set

contains

   !> (v, w) of point k: the deflection (y, z) of a stacked state `u` (2J values) at its
   !! node (m).
   pure function position(self, k, u) result(r)
      class(circle_set), intent(in) :: self
      integer, intent(in) :: k
      real(dp), intent(in) :: u(:)
      real(dp) :: r(2)
      r = [u(self%dof(k)), u(size(u)/2 + self%dof(k))]
   end function position

   !> r - c of a circle's point k in a stacked state `u` (m).
   pure function offset(self, k, u) result(r)
      class(circle_set), intent(in) :: self
      integer, intent(in) :: k
      real(dp), intent(in) :: u(:)
      real(dp) :: r(2)
      r = self%position(k, u) - self%center(:, k)
   end function offset

   !> The distance of the position `r` = (v, w) from point k's wall, positive on the
   !! allowed side (m): R - |r - c| for a circle, h.r - b for a flat point.
   pure real(dp) function gap_at(self, k, r)
      class(circle_set), intent(in) :: self
      integer, intent(in) :: k
      real(dp), intent(in) :: r(2)
      if (self%flat(k)) then
         gap_at = dot_product(self%normal(:, k), r) - self%bound(k)
      else
         gap_at = self%radius(k) - norm2(r - self%center(:, k))
      end if
   end function gap_at

   !> The inward unit normal of point k's wall at the position `r` = (v, w): -(r - c)/|r - c|
   !! for a circle (the direction from the point to the centre), h for a flat point.
   pure function normal_at(self, k, r) result(h)
      class(circle_set), intent(in) :: self
      integer, intent(in) :: k
      real(dp), intent(in) :: r(2)
      real(dp) :: h(2)
      if (self%flat(k)) then
         h = self%normal(:, k)
      else
         h = -(r - self%center(:, k))/norm2(r - self%center(:, k))
      end if
   end function normal_at

   !> How far point k is beyond its wall in a stacked state `u` (m, > 0 beyond): the
   !! radial penetration |r - c| - R of a circle, b - h.(v, w) of a flat point.
   pure real(dp) function penetration(self, k, u)
      class(circle_set), intent(in) :: self
      integer, intent(in) :: k
      real(dp), intent(in) :: u(:)
      penetration = -self%gap_at(k, self%position(k, u))
   end function penetration

   !> Has any point a friction coefficient (and so the run a friction ledger)?
   pure logical function frictional(self)
      class(circle_set), intent(in) :: self
      frictional = .false.
      if (allocated(self%friction)) frictional = any(self%friction > 0)
   end function frictional
end module vibrobeam_circle_set
