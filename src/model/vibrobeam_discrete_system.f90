!> What a time stepper steps: the mass and stiffness matrices, the contact rows and the
!! loads, in the coordinates of the run (the nodal unknowns of the full model, or the
!! coordinates of the reduced model of `&mesh reduction`, `vibrobeam_reduction`). The
!! steppers see only this, so no stepper or run loop asks whether the model is reduced;
!! what maps the coordinates back to the mesh (the reduced basis) stays with the run
!! (`vibrobeam_problem`). A beam of two bending planes steps a state of 2J unknowns,
!! y then z, with the same M and, in z, the stiffness `stiffness_z` when it has its own.
module vibrobeam_discrete_system
   use vibrobeam_model, only: beam_model
   use vibrobeam_contact_set, only: contact_set
   use vibrobeam_loads, only: load_set
   use vibrobeam_band, only: symmetric_band
   use vibrobeam_circle_set, only: circle_set
   implicit none
   private
   public :: discrete_system

   type :: discrete_system
      type(beam_model) :: model       !! M and K (and the mesh's length) in the run's coordinates
      type(contact_set) :: contacts   !! the rows H_c and bounds of the contact points, springs included
      type(load_set) :: loads         !! F(t) in the run's coordinates
      !> bending planes (docs/method.md, "Two bending planes"): 1, or 2 with a state of 2J
      !! unknowns stacked y then z; `model` is the y plane's, M and the rows are both planes'
      integer :: planes = 1
      !> K of the z plane when it differs from the y plane's (E inertia_z); unallocated:
      !! K_z = K
      type(symmetric_band), allocatable :: stiffness_z
      !> the points of circular holes (two planes only; count 0 otherwise)
      type(circle_set) :: circles
   end type discrete_system
end module vibrobeam_discrete_system
