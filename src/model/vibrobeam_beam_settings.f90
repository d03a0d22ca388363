!> The beam and its mesh as the input gives them: &beam (docs/input.md, "&beam") and &mesh
!! ("&mesh"), each variable declared once in `visit_beam` and `visit_mesh`
!! (`vibrobeam_schema_visitor`), with the quantities the model derives from them.
module vibrobeam_beam_settings
   use vibrobeam_kinds, only: dp
   use vibrobeam_status, only: stat_failure
   use vibrobeam_text, only: real_text
   use vibrobeam_schema_visitor, only: schema_visitor, real_row, integer_row, keyword_row, unset, is_unset, &
      unset_integer, keyword_length
   use vibrobeam_boundary, only: boundary_conditions, end_names, end_code, end_clamped, end_free
   use vibrobeam_namelist_schema, only: namelist_variable
   use vibrobeam_frequency_twins, only: hertz_twin
   use vibrobeam_modal_damping, only: max_damped_modes
   use vibrobeam_section_settings, only: section_settings
   implicit none
   private
   public :: beam_settings, mesh_settings, visit_beam, visit_mesh, check_planes

   !> &beam: the beam's length, stiffness and mass (by E, rho, S, I, or by k2 = EI/(rho S)
   !! alone, per unit mass, or section by section: &sections), its end supports and end
   !! springs, its axial force, and its Rayleigh damping.
   type :: beam_settings
      real(dp) :: length = 1                  !! L (m)
      real(dp) :: k2 = 1                      !! EI/(rho S) (m^4/s^2)
      real(dp) :: youngs_modulus = unset      !! E (Pa)
      real(dp) :: density = unset             !! rho (kg/m^3)
      real(dp) :: area = unset                !! S (m^2)
      real(dp) :: inertia = unset             !! I (m^4)
      !> bending planes: 1 (v in y only) or 2 (v in y and w in z; docs/method.md, "Two
      !! bending planes and tube-support contact"); unset: 1, not listed, so that planar
      !! results keep their attributes
      integer :: planes = unset_integer
      !> second moment of area about the y axis, for bending in z (m^4); unset: `inertia`
      !! (listed only when given)
      real(dp) :: inertia_z = unset
      real(dp) :: rayleigh_mass = 0           !! a in C = a M + b K (1/s)
      real(dp) :: rayleigh_stiffness = 0      !! b in C = a M + b K (s)
      !> damping ratio of every mode up to the time step's cut-off (unset: none), and of mode
      !! k (unset: `modal_damping`); `vibrobeam_modal_damping`
      real(dp) :: modal_damping = unset
      real(dp) :: modal_damping_ratios(max_damped_modes) = unset
      !> end supports as given ('' not given: clamped at x = 0, free at x = L; `supports`
      !! resolves them)
      character(len=keyword_length) :: left_end = '', right_end = ''
      !> end springs, translational (N/m) and rotational (N m/rad), per unit rho S when the
      !! beam is given by k2 (like every force); unset: none (listed only when given, so
      !! that the results of a scene without them keep their attributes)
      real(dp) :: left_spring = unset, left_rotational_spring = unset
      real(dp) :: right_spring = unset, right_rotational_spring = unset
      !> axial force T (N, positive in tension; per unit rho S when the beam is given by
      !! k2); unset: none (listed only when given)
      real(dp) :: axial_force = unset
      !> the sections of a non-uniform beam (&sections, `vibrobeam_section_settings`; its
      !! own group, visited by the scene): empty or unallocated for a uniform beam
      type(section_settings), allocatable :: sections(:)
   contains
      procedure :: physical                   !! given by E, rho, S, I (or by sections)?
      procedure :: sectioned                  !! given by sections?
      procedure :: rho_s                      !! mass per unit length (kg/m)
      procedure :: ei                         !! bending stiffness (N m^2)
      procedure :: ei_z                       !! bending stiffness in z (N m^2)
      procedure :: own_z_stiffness            !! does z bend with a stiffness of its own?
      procedure :: tension                    !! the axial force (N; 0 when not given)
      procedure :: supports                   !! the end supports and springs, resolved
      procedure :: modal                      !! is any damping per mode given?
      procedure :: plane_count                !! the bending planes, 1 when not given
   end type beam_settings

   !> &mesh: the finite elements, their basis, and the reduced model of dynamics.
   type :: mesh_settings
      integer :: elements = 32                !! N
      character(len=keyword_length) :: basis = 'hermite'
      character(len=keyword_length) :: reduction = 'none'   !! 'none' | 'craig-bampton' (dynamics only)
      real(dp) :: reduction_frequency = unset   !! cut-off of the fixed-interface modes (rad/s); unset: default
      real(dp) :: reduction_frequency_hz = unset   !! the same in Hz (`vibrobeam_frequency_twins`)
      integer :: reduction_modes = unset_integer   !! number of fixed-interface modes; unset: set by the cut-off
   contains
      procedure :: unknowns                   !! J of the mesh
   end type mesh_settings

contains

   !> Every variable of &beam, once (docs/input.md, "&beam").
   subroutine visit_beam(beam, visitor)
      type(beam_settings), intent(inout) :: beam
      class(schema_visitor), intent(inout) :: visitor
      call visitor%variable(real_row('beam', 'length', 'm', 1e-9_dp, 1e6_dp, 'length L of the beam'), beam%length)
      call visitor%variable(real_row('beam', 'k2', 'm^4/s^2', 1e-30_dp, 1e30_dp, &
                                     'EI/(rho S), when E, rho, S, I are not given (loads are then per unit mass)'), beam%k2)
      call visitor%variable(real_row('beam', 'youngs_modulus', 'Pa', 1.0_dp, 1e13_dp, 'Young''s modulus E', &
                                     optional=.true.), beam%youngs_modulus)
      call visitor%variable(real_row('beam', 'density', 'kg/m^3', 1e-2_dp, 1e6_dp, 'density rho', optional=.true.), &
                            beam%density)
      call visitor%variable(real_row('beam', 'area', 'm^2', 1e-20_dp, 1e4_dp, 'cross-section area S', &
                                     optional=.true.), beam%area)
      call visitor%variable(real_row('beam', 'inertia', 'm^4', 1e-42_dp, 1e8_dp, 'second moment of area I', &
                                     optional=.true.), beam%inertia)
      call visitor%variable(integer_row('beam', 'planes', 1, 2, &
                                        'bending planes: 1 (y) or 2 (y and z; default 1)', optional=.true.), &
                            beam%planes)
      call visitor%variable(real_row('beam', 'inertia_z', 'm^4', 1e-42_dp, 1e8_dp, &
                                     'second moment of area for bending in z (default inertia)', optional=.true.), &
                            beam%inertia_z)
      call visitor%variable(real_row('beam', 'rayleigh_mass', '1/s', 0.0_dp, 1e12_dp, &
                                     'a in the Rayleigh damping C = a M + b K'), beam%rayleigh_mass)
      call visitor%variable(real_row('beam', 'rayleigh_stiffness', 's', 0.0_dp, 1e3_dp, &
                                     'b in the Rayleigh damping C = a M + b K'), beam%rayleigh_stiffness)
      call visitor%variable(real_row('beam', 'modal_damping', '', 0.0_dp, 1.0_dp, &
                                     'damping ratio of every mode the time step resolves (default none)', &
                                     optional=.true.), beam%modal_damping)
      call visitor%variable(real_row('beam', 'modal_damping_ratios', '', 0.0_dp, 1.0_dp, &
                                     'damping ratio of mode k, overriding modal_damping', extent=max_damped_modes, &
                                     optional=.true.), beam%modal_damping_ratios)
      call visitor%variable(keyword_row('beam', 'left_end', end_names, keyword_length, &
                                        'support at x = 0 (default clamped)', optional=.true.), beam%left_end)
      call visitor%variable(keyword_row('beam', 'right_end', end_names, keyword_length, &
                                        'support at x = L (default free)', optional=.true.), beam%right_end)
      call visitor%variable(real_row('beam', 'left_spring', 'N/m', 0.0_dp, 1e30_dp, &
                                     'translational spring at x = 0 (default none)', optional=.true.), beam%left_spring)
      call visitor%variable(real_row('beam', 'left_rotational_spring', 'N m/rad', 0.0_dp, 1e30_dp, &
                                     'rotational spring at x = 0 (default none)', optional=.true.), &
                            beam%left_rotational_spring)
      call visitor%variable(real_row('beam', 'right_spring', 'N/m', 0.0_dp, 1e30_dp, &
                                     'translational spring at x = L (default none)', optional=.true.), beam%right_spring)
      call visitor%variable(real_row('beam', 'right_rotational_spring', 'N m/rad', 0.0_dp, 1e30_dp, &
                                     'rotational spring at x = L (default none)', optional=.true.), &
                            beam%right_rotational_spring)
      call visitor%variable(real_row('beam', 'axial_force', 'N', -1e20_dp, 1e20_dp, &
                                     'axial force T, positive in tension (default 0)', optional=.true.), &
                            beam%axial_force)
   end subroutine visit_beam

   !> Every variable of &mesh, once (docs/input.md, "&mesh"); the cut-off also in Hz, its
   !! twin (`vibrobeam_frequency_twins`).
   subroutine visit_mesh(mesh, visitor)
      type(mesh_settings), intent(inout) :: mesh
      class(schema_visitor), intent(inout) :: visitor
      type(namelist_variable) :: row
      call visitor%variable(integer_row('mesh', 'elements', 1, 1000000, 'number of elements N (uniform mesh)'), &
                            mesh%elements)
      call visitor%variable(keyword_row('mesh', 'basis', 'hermite|bspline', keyword_length, &
                                        'Hermite cubic elements or cubic B-splines'), mesh%basis)
      call visitor%variable(keyword_row('mesh', 'reduction', 'none|craig-bampton', keyword_length, &
                                        'dynamics on the full model or on a Craig-Bampton reduced model'), mesh%reduction)
      row = real_row('mesh', 'reduction_frequency', 'rad/s', 1e-30_dp, 1e30_dp, &
                     'cut-off of the fixed-interface modes the reduced model keeps', optional=.true.)
      call visitor%variable(row, mesh%reduction_frequency)
      call visitor%variable(hertz_twin(row), mesh%reduction_frequency_hz)
      call visitor%variable(integer_row('mesh', 'reduction_modes', 0, 100000, &
                                        'number of fixed-interface modes the reduced model keeps', optional=.true.), &
                            mesh%reduction_modes)
   end subroutine visit_mesh

   !> True when the beam is given by E, rho, S, I, or by sections (then k2 = EI/(rho S)).
   pure logical function physical(self)
      class(beam_settings), intent(in) :: self
      physical = self%sectioned() .or. .not. all(is_unset([self%youngs_modulus, self%density, self%area, self%inertia]))
   end function physical

   !> True when the beam is given section by section (&sections; &beam's E, rho, S, I and
   !! k2 are then not used).
   pure logical function sectioned(self)
      class(beam_settings), intent(in) :: self
      sectioned = .false.
      if (allocated(self%sections)) sectioned = size(self%sections) > 0
   end function sectioned

   !> Mass per unit length rho S (kg/m); 1 when the beam is given by k2; the mean over the
   !! length of a beam of sections (sum of rho_i S_i times each section's length, over L).
   pure real(dp) function rho_s(self)
      class(beam_settings), intent(in) :: self
      if (self%sectioned()) then
         rho_s = length_mean(self, self%sections%rho_s())
      else if (self%physical()) then
         rho_s = self%density*self%area
      else
         rho_s = 1
      end if
   end function rho_s

   !> Bending stiffness E I (N m^2); k2 when the beam is given by k2; the mean over the
   !! length of a beam of sections.
   pure real(dp) function ei(self)
      class(beam_settings), intent(in) :: self
      if (self%sectioned()) then
         ei = length_mean(self, self%sections%ei())
      else if (self%physical()) then
         ei = self%youngs_modulus*self%inertia
      else
         ei = self%k2
      end if
   end function ei

   !> Bending stiffness of the z plane (N m^2): E inertia_z when inertia_z is given (a beam
   !! of the four physical data, `check_planes`), else the y plane's `ei`.
   pure real(dp) function ei_z(self)
      class(beam_settings), intent(in) :: self
      if (self%own_z_stiffness()) then
         ei_z = self%youngs_modulus*self%inertia_z
      else
         ei_z = self%ei()
      end if
   end function ei_z

   !> Does the z plane have a stiffness of its own (planes = 2 with an inertia_z that is
   !! not `inertia`)? Else K_z = K and the two planes share the factor of W.
   pure logical function own_z_stiffness(self)
      class(beam_settings), intent(in) :: self
      own_z_stiffness = self%plane_count() == 2 .and. .not. is_unset(self%inertia_z)
      if (own_z_stiffness) own_z_stiffness = abs(self%inertia_z - self%inertia) > 0
   end function own_z_stiffness

   !> The mean over [0, L] of a value given per section (section i from the previous
   !! one's end, or 0, to its x_to; the last to L): sum_i value_i (x_i - x_(i-1))/L.
   pure real(dp) function length_mean(beam, values)
      type(beam_settings), intent(in) :: beam
      real(dp), intent(in) :: values(:)   !! one per section
      real(dp) :: start, finish
      integer :: i
      length_mean = 0
      start = 0
      do i = 1, size(values)
         finish = merge(beam%length, beam%sections(i)%x_to, i == size(values))
         length_mean = length_mean + values(i)*(finish - start)
         start = finish
      end do
      length_mean = length_mean/beam%length
   end function length_mean

   !> The axial force T (N, positive in tension; per unit rho S when the beam is given by
   !! k2); 0 when not given.
   pure real(dp) function tension(self)
      class(beam_settings), intent(in) :: self
      tension = 0
      if (.not. is_unset(self%axial_force)) tension = self%axial_force
   end function tension

   !> The end supports and end springs of the beam (docs/input.md, "&beam"): left_end and
   !! right_end, clamped and free when not given; a spring not given is none.
   pure function supports(self) result(boundary)
      class(beam_settings), intent(in) :: self
      type(boundary_conditions) :: boundary
      boundary%left = end_code(self%left_end)
      if (boundary%left == 0) boundary%left = end_clamped
      boundary%right = end_code(self%right_end)
      if (boundary%right == 0) boundary%right = end_free
      boundary%left_spring = given(self%left_spring)
      boundary%left_rotational_spring = given(self%left_rotational_spring)
      boundary%right_spring = given(self%right_spring)
      boundary%right_rotational_spring = given(self%right_rotational_spring)
   contains
      pure real(dp) function given(value)
         real(dp), intent(in) :: value
         given = 0
         if (.not. is_unset(value)) given = value
      end function given
   end function supports

   !> Is a damping ratio per mode given (`modal_damping` or any `modal_damping_ratios`)?
   pure logical function modal(self)
      class(beam_settings), intent(in) :: self
      modal = .not. (is_unset(self%modal_damping) .and. all(is_unset(self%modal_damping_ratios)))
   end function modal

   !> The bending planes (docs/input.md, "&beam"): `planes`, 1 when not given.
   pure integer function plane_count(self)
      class(beam_settings), intent(in) :: self
      plane_count = 1
      if (self%planes /= unset_integer) plane_count = self%planes
   end function plane_count

   !> &beam planes and inertia_z (docs/input.md, "&beam"; docs/method.md, "Two bending
   !! planes and tube-support contact"): `inertia_z` belongs to a beam of two planes given
   !! by its four physical data (a beam of k2 or of sections has no z stiffness of its own
   !! yet). What else a beam of two planes does not take yet is the scene's rule
   !! (`vibrobeam_scene_rules`, `plane_rules`).
   subroutine check_planes(beam, stat, errmsg)
      type(beam_settings), intent(in) :: beam
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      character(len=:), allocatable :: given
      errmsg = ''
      if (.not. is_unset(beam%inertia_z)) then
         given = '&beam inertia_z = '//real_text(beam%inertia_z)//' m^4 '
         if (beam%plane_count() == 1) then
            errmsg = given//'is given with planes = 1: a planar beam bends in y only, about inertia; give '// &
                     'planes = 2 or remove inertia_z'
         else if (beam%sectioned() .or. .not. beam%physical()) then
            errmsg = given//'needs a beam given by youngs_modulus, density, area and inertia (not by k2 or '// &
                     '&sections); remove inertia_z or give the four'
         end if
      end if
      stat = merge(stat_failure, 0, len_trim(errmsg) > 0)
   end subroutine check_planes

   !> Unknowns J of the mesh whose supports impose `held` conditions (a held deflection or
   !! rotation each; `beam_structure%held_count`; 2, the clamp, when absent): its degrees
   !! of freedom, 2(N + 1) (Hermite) or N + 3 (B-splines), less these: 2N or N + 1 for the
   !! clamped-free beam.
   pure integer function unknowns(self, held)
      class(mesh_settings), intent(in) :: self
      integer, intent(in), optional :: held
      integer :: conditions
      conditions = 2
      if (present(held)) conditions = held
      unknowns = merge(2*self%elements + 2, self%elements + 3, self%basis == 'hermite') - conditions
   end function unknowns
end module vibrobeam_beam_settings
