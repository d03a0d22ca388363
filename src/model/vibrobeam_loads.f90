!> External loads of a scene as a function of time (docs/input.md `&load`, theory §1).
!!
!! F(t) = q(t) F_q + P(t) F_p + rho S A Omega_b^2 sin(Omega_b t) F_q (A Omega_b^2 given as
!! &load base_acceleration, or from base_amplitude A), where F_q is the
!! consistent load vector of a unit uniform load, F_p that of a unit point force, q(t) =
!! distributed cos(Omega t + phi) and P(t) = point_force cos(Omega_p t). The last term is
!! base excitation: in the frame of the support s(t) = A sin(Omega_b t) the beam feels the
!! inertial load -rho S s''(t). Displacements are then relative to the support, and the
!! obstacles move with the support (they are fixed in its frame).
module vibrobeam_loads
   use vibrobeam_kinds, only: dp
   use vibrobeam_scene, only: scene_type
   use vibrobeam_model, only: beam_model, load_vector, point_load_vector, unit_profile
   implicit none
   private
   public :: load_set, build_loads

   type :: load_set
      logical :: present = .false.           !! false: F(t) = 0, nothing to compute
      real(dp), allocatable :: uniform(:)    !! F_q (J)
      real(dp), allocatable :: point(:)      !! F_p (J)
      real(dp) :: distributed = 0, distributed_frequency = 0, distributed_phase = 0
      real(dp) :: point_force = 0, point_frequency = 0
      real(dp) :: base_load = 0              !! rho S A Omega_b^2 (N/m)
      real(dp) :: base_frequency = 0
   contains
      procedure :: at => load_at
      procedure :: evaluate => load_evaluate
   end type load_set

contains

   subroutine build_loads(scene, model, rho_s, loads)
      type(scene_type), intent(in) :: scene
      type(beam_model), intent(in) :: model
      real(dp), intent(in) :: rho_s
      type(load_set), intent(out) :: loads
      loads%distributed = scene%distributed
      loads%distributed_frequency = scene%distributed_frequency
      loads%distributed_phase = scene%distributed_phase
      loads%point_force = scene%point_force
      loads%point_frequency = scene%point_frequency
      if (abs(scene%base_acceleration) > 0) then
         loads%base_load = rho_s*scene%base_acceleration
      else
         loads%base_load = rho_s*scene%base_amplitude*scene%base_frequency**2
      end if
      loads%base_frequency = scene%base_frequency
      loads%present = abs(loads%distributed) > 0 .or. abs(loads%point_force) > 0 .or. abs(loads%base_load) > 0
      loads%uniform = load_vector(model, unit_profile)
      if (abs(loads%point_force) > 0) then
         loads%point = point_load_vector(model, scene%point_position)
      else
         allocate (loads%point(model%unknowns), source=0.0_dp)
      end if
   end subroutine build_loads

   !> F(t) (N per unknown; per unit mass when the beam is given by k2).
   pure function load_at(self, t) result(f)
      class(load_set), intent(in) :: self
      real(dp), intent(in) :: t   !! time (s)
      real(dp) :: f(size(self%uniform))
      call load_evaluate(self, t, f)
   end function load_at

   !> F(t) into f (the time steppers: no temporary array).
   pure subroutine load_evaluate(self, t, f)
      class(load_set), intent(in) :: self
      real(dp), intent(in) :: t   !! time (s)
      real(dp), intent(out) :: f(:)   !! (J)
      f = 0
      if (.not. self%present) return
      f = (self%distributed*cos(self%distributed_frequency*t + self%distributed_phase) + &
           self%base_load*sin(self%base_frequency*t))*self%uniform
      if (abs(self%point_force) > 0) f = f + self%point_force*cos(self%point_frequency*t)*self%point
   end subroutine load_evaluate
end module vibrobeam_loads
