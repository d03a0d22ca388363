!> Fluid-elastic coupling of a tube in cross-flow (&flow, docs/input.md; docs/theory.md
!! section 10): a force that grows with the flow velocity U and feeds the tube's motion,
!! modelled as a negative damping of its lowest natural modes whose linear stability
!! threshold is Connors' critical velocity exactly.
!!
!! Mode n of the beam without obstacles (omega_n, M-orthogonal shape phi_n, modal mass
!! m_n = phi_n^T M phi_n, structural damping ratio zeta_n = a/(2 omega_n) + b omega_n/2 of
!! the Rayleigh damping) receives the modal force 2 zeta_f,n omega_n q_n' with
!!
!!     zeta_f,n = rho U^2 J_n / (2 pi K^2 m f_n^2),   f_n = omega_n/(2 pi),
!!
!! rho the fluid's density, m = rho S the tube's mass per unit length, K Connors' constant
!! and J_n the share of the mode's kinetic energy in the span [x_from, x_to] in cross-flow.
!! Mode n becomes unstable when zeta_f,n = zeta_n, i.e. at
!!
!!     U_c,n = K f_n sqrt(2 pi zeta_n m/(rho J_n)) = K f_n d sqrt(2 pi zeta_n m/(rho d^2 J_n)),
!!
!! Connors' formula (J_n = 1 on the whole span). On the unknowns the force is
!! F_f = sum_n g_n (M phi_n)(M phi_n)^T V, g_n = 2 zeta_f,n omega_n/m_n: the velocity
!! scheme adds it to F^{n+theta} at V^n (`vibrobeam_velocity_stepper`). A beam of two
!! planes receives it in each plane (the flow feeds both transverse motions alike, with
!! one Connors constant): on the y plane's modes in z too while the planes share K, on the
!! z plane's own modes when it has a stiffness of its own (`take_z_plane`).
module vibrobeam_flow
   use vibrobeam_kinds, only: dp, pi
   use vibrobeam_status, only: stat_failure, stat_numerical_failure
   use vibrobeam_text, only: real_text, integer_text, short_text
   use vibrobeam_band, only: band_matvec
   use vibrobeam_lapack, only: dgemv
   use vibrobeam_schema_visitor, only: schema_visitor, real_row, integer_row, keyword_row, unset, is_unset, &
      keyword_length
   use vibrobeam_namelist_scanned, only: scanned_file
   use vibrobeam_model, only: beam_model, point_row, gauss_points, gauss_weights
   use vibrobeam_modes, only: compute_modes
   implicit none
   private
   public :: flow_settings, visit_flow, check_flow, fluid_elastic, build_flow, ignored_flow

   !> &flow as the input gives it (docs/input.md, "&flow").
   type :: flow_settings
      real(dp) :: velocity = 0                      !! U, the cross-flow velocity (m/s)
      real(dp) :: density = 1000                    !! rho, the fluid's density (kg/m^3)
      real(dp) :: diameter = unset                  !! d, the tube's outer diameter (m); for reports
      real(dp) :: x_from = 0                        !! the span in cross-flow (m)
      real(dp) :: x_to = unset                      !! its end (m); default L
      real(dp) :: connors_constant = 3              !! K
      character(len=keyword_length) :: model = 'modal-damping'
      integer :: modes = 4                          !! the lowest modes the force acts on (at most J)
   end type flow_settings

   !> The fluid-elastic force on the unknowns (module documentation).
   type :: fluid_elastic
      logical :: active = .false.                   !! U > 0: the force acts
      integer :: count = 0                          !! modes
      real(dp) :: velocity = 0                      !! U (m/s)
      real(dp) :: diameter = 0                      !! d (m; 0: not given)
      real(dp) :: mass_per_length = 0               !! m = rho S (kg/m)
      real(dp) :: fluid_density = 0                 !! rho (kg/m^3)
      real(dp) :: connors_constant = 0              !! K
      real(dp), allocatable :: omega(:)             !! (count) omega_n (rad/s)
      real(dp), allocatable :: zeta(:)              !! (count) structural damping ratios
      real(dp), allocatable :: span_share(:)        !! (count) J_n
      real(dp), allocatable :: critical(:)          !! (count) U_c,n (m/s)
      real(dp), allocatable :: fluid_zeta(:)        !! (count) zeta_f,n at U
      real(dp), allocatable :: gain(:)              !! (count) g_n (1/(s kg))
      real(dp), allocatable :: rows(:, :)           !! (count, J) (M phi_n)^T, a row per mode
      !> a beam of two planes whose z plane has a stiffness of its own: the force on its
      !! modes (`take_z_plane`), the same quantities as above
      logical :: own_z = .false.
      real(dp), allocatable :: omega_z(:), zeta_z(:), span_share_z(:), critical_z(:), fluid_zeta_z(:), gain_z(:)
      real(dp), allocatable :: rows_z(:, :)
   contains
      procedure :: add_force
      procedure :: take_z_plane
      procedure :: take_modal_rates
      procedure :: project
      procedure :: report
      procedure :: unbounded_warning
   end type fluid_elastic

contains

   !> Every variable of &flow, once (docs/input.md, "&flow"). x_to's default, the tip, is
   !! taken where the force is built (a sweep of &beam length moves it).
   subroutine visit_flow(flow, visitor)
      type(flow_settings), intent(inout) :: flow
      class(schema_visitor), intent(inout) :: visitor
      call visitor%variable(real_row('flow', 'velocity', 'm/s', 0.0_dp, 1e6_dp, &
                                     'cross-flow velocity U (0: no fluid-elastic force)'), flow%velocity)
      call visitor%variable(real_row('flow', 'density', 'kg/m^3', 1e-6_dp, 1e6_dp, 'density rho of the fluid'), &
                            flow%density)
      call visitor%variable(real_row('flow', 'diameter', 'm', 1e-9_dp, 1e3_dp, &
                                     'outer diameter d of the tube (reduced velocities in reports)', optional=.true.), &
                            flow%diameter)
      call visitor%variable(real_row('flow', 'x_from', 'm', 0.0_dp, 1e6_dp, 'start of the span in cross-flow'), &
                            flow%x_from)
      call visitor%variable(real_row('flow', 'x_to', 'm', 0.0_dp, 1e6_dp, &
                                     'end of the span in cross-flow (default: the tip)', optional=.true.), flow%x_to)
      call visitor%variable(real_row('flow', 'connors_constant', '', 1e-3_dp, 1e3_dp, &
                                     'Connors'' constant K of U_c = K f d sqrt(2 pi zeta m/(rho d^2))'), &
                            flow%connors_constant)
      call visitor%variable(keyword_row('flow', 'model', 'modal-damping', keyword_length, &
                                        'the time-domain fluid-elastic model'), flow%model)
      call visitor%variable(integer_row('flow', 'modes', 1, 1000, 'the lowest modes the force acts on'), flow%modes)
   end subroutine visit_flow

   !> The rules between the variables of &flow (docs/input.md, "&flow") for a beam of
   !! `length` (m), stepped by `scheme`, with `unknowns` J. stat = stat_failure and a message
   !! naming the variable, its value and what is allowed at the first violation.
   subroutine check_flow(flow, length, scheme, unknowns, dynamics, stat, errmsg)
      type(flow_settings), intent(in) :: flow
      real(dp), intent(in) :: length
      character(len=*), intent(in) :: scheme
      integer, intent(in) :: unknowns
      logical, intent(in) :: dynamics
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      real(dp) :: x_to
      stat = 0
      errmsg = ''
      if (.not. dynamics .or. flow%velocity <= 0) return
      x_to = length
      if (.not. is_unset(flow%x_to)) x_to = flow%x_to
      if (x_to > length) then
         call fail('&flow x_to = '//real_text(x_to)//' is outside [x_from, length] = ['//real_text(flow%x_from)//', '// &
                   real_text(length)//'] m')
      else if (x_to <= flow%x_from) then
         call fail('&flow x_from = '//real_text(flow%x_from)//' is not below x_to = '//real_text(x_to)// &
                   ' m: the span in cross-flow needs a positive length')
      else if (scheme /= 'velocity') then
         call fail('&flow velocity = '//real_text(flow%velocity)//' m/s needs &time scheme = ''velocity'' (the '// &
                   'fluid-elastic force is evaluated at V^n of that scheme); the scheme is '''//trim(scheme)//'''')
      else if (flow%modes > unknowns) then
         call fail('&flow modes = '//integer_text(flow%modes)//' is outside [1, '//integer_text(unknowns)// &
                   '], the unknowns J of the mesh')
      end if
   contains
      subroutine fail(message)
         character(len=*), intent(in) :: message
         stat = stat_failure
         errmsg = message
      end subroutine fail
   end subroutine check_flow

   !> The fluid-elastic force of `settings` on `model` (rho S in kg/m), for the Rayleigh
   !! damping a (1/s), b (s) of the beam (module documentation). Inactive when U = 0.
   !! stat = stat_numerical_failure when the modes cannot be computed (their message).
   subroutine build_flow(settings, model, rayleigh_mass, rayleigh_stiffness, force, stat, errmsg)
      type(flow_settings), intent(in) :: settings
      type(beam_model), intent(in) :: model
      real(dp), intent(in) :: rayleigh_mass, rayleigh_stiffness
      type(fluid_elastic), intent(out) :: force
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      real(dp), allocatable :: omega(:), shapes(:, :), vectors(:, :)
      real(dp) :: x_to, modal_mass, f, m_phi(model%unknowns)
      integer :: n
      stat = 0
      errmsg = ''
      if (settings%velocity <= 0) return
      force%active = .true.
      force%count = min(settings%modes, model%unknowns)
      force%velocity = settings%velocity
      force%fluid_density = settings%density
      force%connors_constant = settings%connors_constant
      force%mass_per_length = model%rho_s
      force%diameter = 0
      if (.not. is_unset(settings%diameter)) force%diameter = settings%diameter
      x_to = model%length
      if (.not. is_unset(settings%x_to)) x_to = settings%x_to
      call compute_modes(model, force%count, omega, shapes, vectors, stat, errmsg)
      if (stat /= 0) then
         errmsg = '&flow: the modes of the fluid-elastic force: '//trim(errmsg)
         stat = stat_numerical_failure
         return
      end if
      allocate (force%rows(force%count, model%unknowns))
      force%omega = omega
      allocate (force%zeta(force%count), force%span_share(force%count), force%critical(force%count), &
                force%fluid_zeta(force%count), force%gain(force%count))
      do n = 1, force%count
         call band_matvec(model%mass, vectors(:, n), m_phi)
         force%rows(n, :) = m_phi
         modal_mass = dot_product(vectors(:, n), m_phi)
         f = omega(n)/(2*pi)
         force%zeta(n) = rayleigh_mass/(2*omega(n)) + rayleigh_stiffness*omega(n)/2
         force%span_share(n) = span_integral(vectors(:, n), settings%x_from, x_to)/ &
                               span_integral(vectors(:, n), 0.0_dp, model%length)
         force%fluid_zeta(n) = settings%density*settings%velocity**2*force%span_share(n)/ &
                               (2*pi*settings%connors_constant**2*model%rho_s*f**2)
         force%critical(n) = critical_velocity(settings%connors_constant, omega(n), force%zeta(n), model%rho_s, &
                                               settings%density, force%span_share(n))
         force%gain(n) = 2*force%fluid_zeta(n)*omega(n)/modal_mass
      end do
   contains
      !> The integral of rho S u^2 over [a, b] for the unknowns `u` (4-point Gauss rule on the
      !! part of each element inside [a, b], exact for cubic u).
      real(dp) function span_integral(u, a, b)
         real(dp), intent(in) :: u(:), a, b
         real(dp) :: lo, hi, weights(4), value
         integer :: e, g, dofs(4), k
         span_integral = 0
         do e = 1, model%elements
            lo = max(a, model%x(e))
            hi = min(b, model%x(e + 1))
            if (hi <= lo) cycle
            do g = 1, 4
               call point_row(model, lo + gauss_points(g)*(hi - lo), dofs, weights)
               value = 0
               do k = 1, 4
                  if (dofs(k) /= 0) value = value + weights(k)*u(dofs(k))
               end do
               span_integral = span_integral + gauss_weights(g)*(hi - lo)*model%rho_s*value**2
            end do
         end do
      end function span_integral
   end subroutine build_flow

   !> f += F_f(V) = sum_n g_n (M phi_n) ((M phi_n)^T V) (module documentation): the modes'
   !! velocities q_n' = (M phi_n)^T V, then the force, two products with BLAS dgemv. A beam
   !! of two planes (2J velocities, y then z): in each plane, with the z plane's own modes
   !! when it has them.
   subroutine add_force(self, v, f)
      class(fluid_elastic), intent(in) :: self
      real(dp), intent(in) :: v(:)      !! velocities of the unknowns
      real(dp), intent(inout) :: f(:)
      integer :: j
      j = size(self%rows, 2)
      call add_plane(self%rows, self%gain, v(1:j), f(1:j))
      if (size(v) == j) return
      if (self%own_z) then
         call add_plane(self%rows_z, self%gain_z, v(j + 1:), f(j + 1:))
      else
         call add_plane(self%rows, self%gain, v(j + 1:), f(j + 1:))
      end if
   contains
      subroutine add_plane(rows, gain, v, f)
         real(dp), intent(in) :: rows(:, :), gain(:), v(:)
         real(dp), intent(inout) :: f(:)
         real(dp) :: c(size(gain))
         integer :: m, n
         m = size(gain)
         n = size(v)
         call dgemv('N', m, n, 1.0_dp, rows, m, v, 1, 0.0_dp, c, 1)
         c = gain*c
         call dgemv('T', m, n, 1.0_dp, rows, m, c, 1, 1.0_dp, f, 1)
      end subroutine add_plane
   end subroutine add_force

   !> Connors' critical velocity U_c = K f sqrt(2 pi zeta m/(rho J)) of a mode of angular
   !! frequency omega (f = omega/(2 pi)), structural damping ratio zeta, span share J, on a
   !! beam of mass per length m in a fluid of density rho (module documentation).
   elemental real(dp) function critical_velocity(connors, omega, zeta, mass_per_length, fluid_density, share)
      real(dp), intent(in) :: connors, omega, zeta, mass_per_length, fluid_density, share
      critical_velocity = connors*(omega/(2*pi))*sqrt(2*pi*zeta*mass_per_length/(fluid_density*share))
   end function critical_velocity

   !> The damping per mode of &beam (`vibrobeam_modal_damping`): `rates` c_k (1/s) beyond
   !! the Rayleigh damping of the first modes of the y plane (and `rates_z` of a z plane
   !! with a stiffness of its own), the same modes as this force's, raise those modes'
   !! structural damping ratio by c_k/(2 omega_k), to the ratio given, and with it their
   !! critical velocity: what --check lists and the unbounded-motion warning compares. The
   !! force itself does not depend on zeta.
   subroutine take_modal_rates(self, rates, rates_z)
      class(fluid_elastic), intent(inout) :: self
      real(dp), intent(in) :: rates(:), rates_z(:)
      if (.not. self%active) return
      call raise(self%omega, self%zeta, self%span_share, self%critical, rates)
      if (self%own_z) call raise(self%omega_z, self%zeta_z, self%span_share_z, self%critical_z, rates_z)
   contains
      subroutine raise(omega, zeta, share, critical, c)
         real(dp), intent(in) :: omega(:), share(:), c(:)
         real(dp), intent(inout) :: zeta(:), critical(:)
         integer :: n
         do n = 1, min(size(omega), size(c))
            if (.not. omega(n) > 0) cycle
            zeta(n) = zeta(n) + c(n)/(2*omega(n))
            critical(n) = critical_velocity(self%connors_constant, omega(n), zeta(n), self%mass_per_length, &
                                            self%fluid_density, share(n))
         end do
      end subroutine raise
   end subroutine take_modal_rates

   !> The z plane of a beam of two planes with a stiffness of its own: `z`, the force built
   !! on that plane's model (`build_flow`), becomes this force's z part.
   subroutine take_z_plane(self, z)
      class(fluid_elastic), intent(inout) :: self
      type(fluid_elastic), intent(in) :: z
      if (.not. z%active) return
      self%own_z = .true.
      self%omega_z = z%omega
      self%zeta_z = z%zeta
      self%span_share_z = z%span_share
      self%critical_z = z%critical
      self%fluid_zeta_z = z%fluid_zeta
      self%gain_z = z%gain
      self%rows_z = z%rows
   end subroutine take_z_plane

   !> The force on other coordinates y, U = T y: each M phi_n becomes T^T M phi_n
   !! (`vibrobeam_reduction`'s reduce_loads).
   subroutine project(self, transform)
      class(fluid_elastic), intent(inout) :: self
      real(dp), intent(in) :: transform(:, :)   !! T (J, r)
      if (self%count == 0) return
      self%rows = matmul(self%rows, transform)
   end subroutine project

   !> What `vibrobeam --check` says of the fluid-elastic force: per mode, its frequency,
   !! structural damping, share of the span, Connors' critical velocity and the fluid's
   !! damping ratio at U ('' when the force is inactive).
   function report(self) result(text)
      class(fluid_elastic), intent(in) :: self
      character(len=:), allocatable :: text
      integer :: n
      text = ''
      if (.not. self%active) return
      text = 'fluid-elastic force at U = '//short_text(self%velocity)//' m/s (Connors, modal damping):'//new_line('a')
      call add_modes('', self%omega, self%zeta, self%span_share, self%critical, self%fluid_zeta)
      if (self%own_z) then
         text = text//'  the z plane (its own stiffness):'//new_line('a')
         call add_modes('z ', self%omega_z, self%zeta_z, self%span_share_z, self%critical_z, self%fluid_zeta_z)
      end if
   contains
      subroutine add_modes(plane, omega, zeta, span_share, critical, fluid_zeta)
         character(len=*), intent(in) :: plane
         real(dp), intent(in) :: omega(:), zeta(:), span_share(:), critical(:), fluid_zeta(:)
         do n = 1, size(omega)
            text = text//'  '//plane//'mode '//integer_text(n)//': f = '//short_text(omega(n)/(2*pi))//' Hz, zeta = '// &
                   short_text(zeta(n))//', span share J = '//short_text(span_share(n))// &
                   ', critical velocity U_c = '//short_text(critical(n))//' m/s'
            if (self%diameter > 0) text = text//' (U_c/(f d) = '// &
                                          short_text(critical(n)/(omega(n)/(2*pi)*self%diameter))//')'
            text = text//', fluid damping ratio at U '//short_text(-fluid_zeta(n))
            if (self%velocity > critical(n)) text = text//' (UNSTABLE without contact)'
            text = text//new_line('a')
         end do
      end subroutine add_modes
   end function report

   !> A warning when the flow velocity exceeds the critical velocity of a mode and nothing
   !! bounds the motion (`bounded` false: the scene has no obstacle): without contact that
   !! mode's amplitude grows as exp(-zeta_total omega t), so a long enough run reaches any
   !! size (or overflows, a numerical failure) while each step is computed correctly.
   !! '' when every mode is stable or the stops bound it.
   function unbounded_warning(self, bounded) result(text)
      class(fluid_elastic), intent(in) :: self
      logical, intent(in) :: bounded
      character(len=:), allocatable :: text
      integer :: n
      text = ''
      if (.not. self%active .or. bounded) return
      call first_unstable('', self%critical, self%fluid_zeta, self%zeta)
      if (len(text) == 0 .and. self%own_z) call first_unstable('the z plane''s ', self%critical_z, self%fluid_zeta_z, &
                                                              self%zeta_z)
   contains
      subroutine first_unstable(plane, critical, fluid_zeta, zeta)
         character(len=*), intent(in) :: plane
         real(dp), intent(in) :: critical(:), fluid_zeta(:), zeta(:)
         do n = 1, size(critical)
            if (self%velocity <= critical(n)) cycle
            text = '&flow velocity = '//short_text(self%velocity)//' m/s exceeds the critical velocity of '// &
                   plane//'mode '//integer_text(n)//' (U_c = '//short_text(critical(n))//' m/s) and no obstacle '// &
                   'bounds the motion: its amplitude grows as exp('//short_text(fluid_zeta(n) - zeta(n))// &
                   ' omega_'//integer_text(n)//' t) without end (vibrobeam --check lists every mode)'//new_line('a')
            return
         end do
      end subroutine first_unstable
   end function unbounded_warning

   !> Warnings for &flow values given that the run does not use (docs/input.md,
   !! "Warnings"): the group without a flow velocity, or for an analysis that steps no
   !! motion (`dynamics`: kind = 'dynamics' or 'periodic').
   subroutine ignored_flow(scanned, flow, dynamics, swept_velocity, warnings)
      type(scanned_file), intent(in) :: scanned
      type(flow_settings), intent(in) :: flow
      logical, intent(in) :: dynamics, swept_velocity
      character(len=:), allocatable, intent(inout) :: warnings
      if (.not. scanned%group_given('flow')) return
      if (.not. dynamics) then
         warnings = warnings//'&flow is ignored: the fluid-elastic force acts on the motion (kind = ''dynamics'' '// &
                    'or ''periodic'')'//new_line('a')
      else if (flow%velocity <= 0 .and. .not. swept_velocity) then
         warnings = warnings//'&flow is ignored: velocity = 0 m/s (no fluid-elastic force)'//new_line('a')
      end if
   end subroutine ignored_flow
end module vibrobeam_flow
