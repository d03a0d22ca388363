!> External loads of a scene as a function of time (docs/input.md `&load`, theory §1).
!!
!! F(t) = q(t) F_q + P(t) F_p + rho S A Omega_b^2 sin(Omega_b t) F_q (A Omega_b^2 given as
!! &load base_acceleration, or from base_amplitude A), where F_q is the
!! consistent load vector of a unit uniform load, F_p that of a unit point force, q(t) =
!! distributed cos(Omega t + phi) and P(t) = point_force cos(Omega_p t). The last term is
!! base excitation: in the frame of the support s(t) = A sin(Omega_b t) the beam feels the
!! inertial load -rho S s''(t) (the rho S of each section on a beam of &sections), and
!! each point mass m_k (&masses) the point force -m_k s''(t) at x_k. Displacements are then relative to the support, and the obstacles
!! move with the support (they are fixed in its frame).
!!
!! The loads of &forces (`vibrobeam_forces`: any number of point, distributed and base
!! loads with harmonic, table or random signals) are added to these, and so is the
!! fluid-elastic force of &flow (`vibrobeam_flow`), which depends on the velocities: the
!! velocity scheme adds it at V^n.
module vibrobeam_loads
   use vibrobeam_kinds, only: dp
   use vibrobeam_planes, only: direction_shares, spread_planes
   use vibrobeam_model, only: beam_model, load_vector, point_load_vector, unit_profile, add_inertial_excess
   use vibrobeam_schema_visitor, only: schema_visitor, real_row, unset, is_unset
   use vibrobeam_namelist_schema, only: namelist_variable
   use vibrobeam_frequency_twins, only: hertz_twin
   use vibrobeam_force_settings, only: forces_settings
   use vibrobeam_forces, only: force_set, build_forces
   use vibrobeam_flow, only: fluid_elastic, flow_settings, build_flow
   implicit none
   private
   public :: load_set, build_loads, load_settings, visit_load, add_forces, add_flow, add_flow_z

   !> &load as the input gives it (docs/input.md, "&load"): a uniform load, a point force
   !! and a base excitation, each constant or harmonic.
   type :: load_settings
      real(dp) :: distributed = 0, distributed_frequency = 0, distributed_phase = 0
      real(dp) :: point_force = 0, point_position = unset, point_frequency = 0
      real(dp) :: base_amplitude = 0, base_frequency = 0
      real(dp) :: base_acceleration = 0       !! amplitude of the support's acceleration (m/s^2), instead of base_amplitude
      !> the frequencies in Hz (`vibrobeam_frequency_twins`): each the rad/s one over 2 pi
      real(dp) :: distributed_frequency_hz = 0, point_frequency_hz = 0, base_frequency_hz = 0
      !> with &beam planes = 2: the direction of every load of &load, degrees from y towards
      !! z (unset: 0, along y; listed only when given)
      real(dp) :: direction = unset
      !> with &beam planes = 2: the direction of the point force alone (unset: `direction`)
      real(dp) :: point_direction = unset
   contains
      procedure :: base_load_amplitude
   end type load_settings

   type :: load_set
      logical :: present = .false.           !! false: F(t) = 0, nothing to compute
      real(dp), allocatable :: uniform(:)    !! F_q (J)
      real(dp), allocatable :: point(:)      !! F_p (J)
      real(dp) :: distributed = 0, distributed_frequency = 0, distributed_phase = 0
      real(dp) :: point_force = 0, point_frequency = 0
      real(dp) :: base_load = 0              !! rho S A Omega_b^2 (N/m)
      real(dp) :: base_frequency = 0
      !> the share of the base excitation per unit base_load beyond rho S F_q: the point
      !! masses' sum_k (m_k/rho S) phi(x_k) and the sections' int (rho S(x)/rho S - 1) phi
      !! (m; J; `add_inertial_excess`), when the beam carries masses or sections (`masses`)
      logical :: masses = .false.
      real(dp), allocatable :: mass_points(:)
      type(force_set) :: forces              !! the loads of &forces
      type(fluid_elastic) :: flow            !! the fluid-elastic force of &flow (flow%active: it acts)
      !> (cos, sin) of &load direction: a stepper of two planes turns F(t), given in y, by
      !! them (`spread_planes`); (1, 0) along y
      real(dp) :: shares(2) = [1.0_dp, 0.0_dp]
      !> (cos, sin) of the point force's own direction (&load point_direction), else `shares`
      real(dp) :: point_shares(2) = [1.0_dp, 0.0_dp]
   contains
      procedure :: at => load_at
      procedure :: evaluate => load_evaluate
      procedure :: planes_at
      procedure :: evaluate_planes
      procedure, private :: turn
   end type load_set

contains

   !> Every variable of &load, once (docs/input.md, "&load"); each frequency also in Hz,
   !! its twin (`vibrobeam_frequency_twins`). point_position's default, the tip, is the
   !! scene reader's (it follows &beam length).
   subroutine visit_load(load, visitor)
      type(load_settings), intent(inout) :: load
      class(schema_visitor), intent(inout) :: visitor
      type(namelist_variable) :: row
      call visitor%variable(real_row('load', 'distributed', 'N/m', -1e15_dp, 1e15_dp, &
                                     'amplitude q of the uniform load q cos(Omega t + phi)'), load%distributed)
      row = real_row('load', 'distributed_frequency', 'rad/s', 0.0_dp, 1e15_dp, 'Omega of the uniform load (0: constant)')
      call visitor%variable(row, load%distributed_frequency)
      call visitor%variable(hertz_twin(row), load%distributed_frequency_hz)
      call visitor%variable(real_row('load', 'distributed_phase', 'rad', -1e6_dp, 1e6_dp, &
                                     'phase phi of the uniform load'), load%distributed_phase)
      call visitor%variable(real_row('load', 'point_force', 'N', -1e15_dp, 1e15_dp, &
                                     'amplitude F of the point force F cos(Omega_p t)'), load%point_force)
      call visitor%variable(real_row('load', 'point_position', 'm', 0.0_dp, 1e6_dp, &
                                     'where the point force acts (default: the tip)', optional=.true.), &
                            load%point_position)
      row = real_row('load', 'point_frequency', 'rad/s', 0.0_dp, 1e15_dp, 'Omega_p of the point force (0: constant)')
      call visitor%variable(row, load%point_frequency)
      call visitor%variable(hertz_twin(row), load%point_frequency_hz)
      call visitor%variable(real_row('load', 'base_amplitude', 'm', -1e6_dp, 1e6_dp, &
                                     'amplitude A of the support motion A sin(Omega_b t)'), load%base_amplitude)
      row = real_row('load', 'base_frequency', 'rad/s', 0.0_dp, 1e15_dp, 'Omega_b of the support motion')
      call visitor%variable(row, load%base_frequency)
      call visitor%variable(hertz_twin(row), load%base_frequency_hz)
      call visitor%variable(real_row('load', 'base_acceleration', 'm/s^2', -1e15_dp, 1e15_dp, &
                                     'amplitude of the support''s acceleration, instead of base_amplitude'), &
                            load%base_acceleration)
      call visitor%variable(real_row('load', 'direction', 'deg', -360.0_dp, 360.0_dp, &
                                     'with &beam planes = 2: direction of the loads, from y towards z (default 0)', &
                                     optional=.true.), load%direction)
      call visitor%variable(real_row('load', 'point_direction', 'deg', -360.0_dp, 360.0_dp, &
                                     'with &beam planes = 2: direction of the point force alone (default direction)', &
                                     optional=.true.), load%point_direction)
   end subroutine visit_load

   !> Amplitude of the support's acceleration, A Omega_b^2 or &load base_acceleration
   !! (m/s^2): the base excitation loads the beam with rho S times this, sin(Omega_b t).
   pure real(dp) function base_load_amplitude(self)
      class(load_settings), intent(in) :: self
      if (abs(self%base_acceleration) > 0) then
         base_load_amplitude = self%base_acceleration
      else
         base_load_amplitude = self%base_amplitude*self%base_frequency**2
      end if
   end function base_load_amplitude

   !> The loads of &load on the model (module documentation): the uniform load, the point
   !! force and the base excitation, whose inertial load acts on rho S (each section's) and
   !! on the point masses of the model's structure.
   subroutine build_loads(load, model, rho_s, loads)
      type(load_settings), intent(in) :: load
      type(beam_model), intent(in) :: model
      real(dp), intent(in) :: rho_s
      type(load_set), intent(out) :: loads
      loads%distributed = load%distributed
      loads%distributed_frequency = load%distributed_frequency
      loads%distributed_phase = load%distributed_phase
      loads%point_force = load%point_force
      loads%point_frequency = load%point_frequency
      if (abs(load%base_acceleration) > 0) then
         loads%base_load = rho_s*load%base_acceleration
      else
         loads%base_load = rho_s*load%base_amplitude*load%base_frequency**2
      end if
      loads%base_frequency = load%base_frequency
      if (.not. is_unset(load%direction)) loads%shares = direction_shares(load%direction)
      loads%point_shares = loads%shares
      if (.not. is_unset(load%point_direction)) loads%point_shares = direction_shares(load%point_direction)
      loads%present = abs(loads%distributed) > 0 .or. abs(loads%point_force) > 0 .or. abs(loads%base_load) > 0
      loads%uniform = load_vector(model, unit_profile)
      ! the base's inertial load acts on the point masses too, -m_k s''(t) at x_k, and on the
      ! sections' rho S beyond rho_s
      allocate (loads%mass_points(model%unknowns), source=0.0_dp)
      call add_inertial_excess(model, rho_s, loads%mass_points)
      loads%masses = model%structure%masses() > 0 .or. any(abs(model%element_rho_s - rho_s) > 0)
      if (abs(loads%point_force) > 0) then
         ! the default position, the tip, when a scene built in code leaves it unset
         loads%point = point_load_vector(model, merge(model%length, load%point_position, is_unset(load%point_position)))
      else
         allocate (loads%point(model%unknowns), source=0.0_dp)
      end if
   end subroutine build_loads

   !> The loads of &forces (`build_forces`), added to `loads`. stat and errmsg as
   !! `build_forces` says (a table that cannot be read, ...).
   subroutine add_forces(loads, settings, model, rho_s, dt, stat, errmsg)
      type(load_set), intent(inout) :: loads
      type(forces_settings), intent(in) :: settings
      type(beam_model), intent(in) :: model
      real(dp), intent(in) :: rho_s   !! kg/m
      real(dp), intent(in) :: dt      !! the sample step of random signals (s)
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      call build_forces(settings, model, rho_s, dt, loads%forces, stat, errmsg)
      loads%present = loads%present .or. loads%forces%count > 0
   end subroutine add_forces

   !> The fluid-elastic force of &flow (`build_flow`) beside the loads; stat and errmsg as
   !! `build_flow` says.
   subroutine add_flow(loads, settings, model, rayleigh_mass, rayleigh_stiffness, stat, errmsg)
      type(load_set), intent(inout) :: loads
      type(flow_settings), intent(in) :: settings
      type(beam_model), intent(in) :: model
      real(dp), intent(in) :: rayleigh_mass, rayleigh_stiffness   !! the beam's damping (1/s, s)
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      call build_flow(settings, model, rayleigh_mass, rayleigh_stiffness, loads%flow, stat, errmsg)
   end subroutine add_flow

   !> The fluid-elastic force on the z plane of a beam of two planes with a stiffness of
   !! its own: on the modes of `model_z`, the model of that plane (`fluid_elastic%take_z_plane`).
   subroutine add_flow_z(loads, settings, model_z, rayleigh_mass, rayleigh_stiffness, stat, errmsg)
      type(load_set), intent(inout) :: loads
      type(flow_settings), intent(in) :: settings
      type(beam_model), intent(in) :: model_z
      real(dp), intent(in) :: rayleigh_mass, rayleigh_stiffness
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      type(fluid_elastic) :: flow_z
      call build_flow(settings, model_z, rayleigh_mass, rayleigh_stiffness, flow_z, stat, errmsg)
      if (stat == 0) call loads%flow%take_z_plane(flow_z)
   end subroutine add_flow_z

   !> F(t) (N per unknown; per unit mass when the beam is given by k2), for a caller that
   !! keeps no state: the same values as `evaluate`, which the steppers use.
   function load_at(self, t) result(f)
      class(load_set), intent(in) :: self
      real(dp), intent(in) :: t   !! time (s)
      real(dp) :: f(size(self%uniform))
      call add_loads(self, t, f)
      if (self%forces%count > 0) call self%forces%add_uncached(t, f)
   end function load_at

   !> F(t) into f (the time steppers: no temporary array; the tables keep their position
   !! and the random signals their block of samples, so a step costs what the loads touch).
   subroutine load_evaluate(self, t, f)
      class(load_set), intent(inout) :: self
      real(dp), intent(in) :: t   !! time (s)
      real(dp), intent(out) :: f(:)   !! (J)
      call add_loads(self, t, f)
      if (self%forces%count > 0) call self%forces%add_to(t, f)
   end subroutine load_evaluate

   !> F(t) of a beam of two planes into f (2J values, y then z; `load_at`'s values): the
   !! loads of &load given in the y plane turned by &load direction, the point force by its
   !! own point_direction when it has one, and each load of &forces by its direction.
   subroutine planes_at(self, t, f)
      class(load_set), intent(in) :: self
      real(dp), intent(in) :: t
      real(dp), intent(out) :: f(:)
      call add_loads(self, t, f(1:size(f)/2))
      call self%turn(t, f)
      if (self%forces%count > 0) call self%forces%add_uncached_planes(t, f)
   end subroutine planes_at

   !> `planes_at` for the steppers (`evaluate`'s values: no temporary, the tables' and
   !! random signals' state).
   subroutine evaluate_planes(self, t, f)
      class(load_set), intent(inout) :: self
      real(dp), intent(in) :: t
      real(dp), intent(out) :: f(:)
      call add_loads(self, t, f(1:size(f)/2))
      call self%turn(t, f)
      if (self%forces%count > 0) call self%forces%add_to_planes(t, f)
   end subroutine evaluate_planes

   !> f(1:J) holds F(t) in y: turn it by `shares` into both planes, the point force by
   !! `point_shares` (taken out of y and put back turned, only when its direction differs).
   pure subroutine turn(self, t, f)
      class(load_set), intent(in) :: self
      real(dp), intent(in) :: t
      real(dp), intent(inout) :: f(:)
      real(dp) :: amplitude
      integer :: j
      j = size(f)/2
      if (all(abs(self%point_shares - self%shares) <= 0) .or. abs(self%point_force) <= 0) then
         call spread_planes(self%shares, f)
         return
      end if
      amplitude = self%point_force*cos(self%point_frequency*t)
      f(1:j) = f(1:j) - amplitude*self%point
      call spread_planes(self%shares, f)
      f(1:j) = f(1:j) + self%point_shares(1)*amplitude*self%point
      f(j + 1:) = f(j + 1:) + self%point_shares(2)*amplitude*self%point
   end subroutine turn

   !> The loads of &load at t into f.
   pure subroutine add_loads(self, t, f)
      type(load_set), intent(in) :: self
      real(dp), intent(in) :: t   !! time (s)
      real(dp), intent(out) :: f(:)   !! (J)
      f = 0
      if (.not. self%present) return
      f = (self%distributed*cos(self%distributed_frequency*t + self%distributed_phase) + &
           self%base_load*sin(self%base_frequency*t))*self%uniform
      if (abs(self%point_force) > 0) f = f + self%point_force*cos(self%point_frequency*t)*self%point
      if (self%masses) f = f + self%base_load*sin(self%base_frequency*t)*self%mass_points
   end subroutine add_loads
end module vibrobeam_loads
