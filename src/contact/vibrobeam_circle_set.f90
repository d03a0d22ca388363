!> The contact points of circular holes in the cross-section of a beam bending in two
!! planes (docs/method.md, "Circular obstacles"): at point k, node `node(k)`, the beam's
!! deflection r = (v, w) must stay inside the circle of radius `radius(k)` about
!! `center(:, k)`, R - |r - c| >= 0. With the state stacked y then z (J unknowns per
!! plane) the point's deflections are the unknowns dof(k) and J + dof(k). Which
!! obstacles give which points is `vibrobeam_obstacles`' job (`build_circle_points`).
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
      real(dp), allocatable :: radius(:)       !! R (m)
      real(dp), allocatable :: center(:, :)    !! (2, count) c = (c_y, c_z) (m)
      integer, allocatable :: obstacle(:)      !! the obstacle (index in &obstacles)
      !> compliant circles (docs/theory.md section 8 on the radial penetration
      !! p = |r - c| - R): stiffness k (N/m^a; 0: rigid), exponent a, Hunt-Crossley alpha
      real(dp), allocatable :: stiffness(:), exponent(:), damping(:)
      logical :: compliant = .false.           !! every point compliant (none rigid)
      real(dp), allocatable :: friction(:)     !! Coulomb's mu at the point's wall (0: frictionless)
   contains
      procedure :: offset                      !! r - c of point k in a stacked state
      procedure :: penetration                 !! p = |r - c| - R of point k
      procedure :: frictional                  !! has any point friction?
   end type circle_set

contains

   !> r - c of point k: the deflection (y, z) of a stacked state `u` (2J values) at its
   !! node, less the centre (m).
   pure function offset(self, k, u) result(r)
      class(circle_set), intent(in) :: self
      integer, intent(in) :: k
      real(dp), intent(in) :: u(:)
      real(dp) :: r(2)
      r = [u(self%dof(k)), u(size(u)/2 + self%dof(k))] - self%center(:, k)
   end function offset

   !> The radial penetration p = |r - c| - R of point k beyond its wall (m, > 0 outside
   !! the circle) in a stacked state `u`.
   pure real(dp) function penetration(self, k, u)
      class(circle_set), intent(in) :: self
      integer, intent(in) :: k
      real(dp), intent(in) :: u(:)
      penetration = norm2(self%offset(k, u)) - self%radius(k)
   end function penetration

   !> Has any point a friction coefficient (and so the run a friction ledger)?
   pure logical function frictional(self)
      class(circle_set), intent(in) :: self
      frictional = .false.
      if (allocated(self%friction)) frictional = any(self%friction > 0)
   end function frictional
end module vibrobeam_circle_set
