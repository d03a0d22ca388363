!> Static equilibrium against the obstacles (theory §7 "Static contact", &analysis kind =
!! 'static' and &initial displacement = 'static'):
!!
!!     U = argmin 1/2 U^T K U - F^T U   subject to   g1(x_c) <= H_c U <= g2(x_c),
!!
!! i.e. the projection of U_free = K^-1 F onto the admissible set in the metric K
!! (`contact_projector%project_admissible`, the machinery of a contact step). Reactions
!! are the multipliers P_c (N; per unit mass when the beam is given by k2), positive
!! upwards. With compliant stops (docs/theory.md section 8) the potential gains
!! sum_j Phi_j(p_j(U)) and Newton's method of `vibrobeam_compliant_solver` finds the
!! minimizer (rigid bounds held by the same projection in each iteration's metric); the
!! reaction of a contact point then adds its springs' forces s_j k_j p_j^a (no damping in
!! statics).
module vibrobeam_static
   use vibrobeam_kinds, only: dp
   use vibrobeam_band, only: symmetric_band, band_cholesky, band_factor, band_solve
   use vibrobeam_contact_set, only: contact_set
   use vibrobeam_contact_projector, only: contact_projector
   use vibrobeam_compliant_law, only: spring_set, rule_mean
   use vibrobeam_compliant_solver, only: compliant_solver, rigid_admissible
   implicit none
   private
   public :: solve_static

contains

   subroutine solve_static(stiffness, contacts, force, contact_regime, u, reaction, iterations, stat, errmsg, &
                           max_iterations, contact_method)
      type(symmetric_band), intent(in) :: stiffness
      type(contact_set), intent(in) :: contacts
      real(dp), intent(in) :: force(:)                 !! F (J)
      character(len=*), intent(in) :: contact_regime   !! 'auto' | 'delassus' | 'band'
      real(dp), intent(out) :: u(:)                    !! equilibrium (J)
      real(dp), intent(out) :: reaction(:)             !! (contacts%count) P_c, 0 if not in contact
      integer, intent(out) :: iterations, stat
      character(len=*), intent(out) :: errmsg
      integer, intent(in), optional :: max_iterations  !! pivots allowed per projection (&solver contact_max_iterations; 0: default)
      character(len=*), intent(in), optional :: contact_method   !! 'newton' (default) | 'pivoting'
      type(band_cholesky) :: factor
      type(contact_projector) :: projector
      real(dp) :: u_free(size(force))
      type(compliant_solver) :: compliant
      type(spring_set) :: springs
      integer :: j
      integer :: no_points(0)
      real(dp) :: no_values(0)
      iterations = 0
      reaction = 0
      call band_factor(stiffness, factor, stat, errmsg)
      if (stat /= 0) return
      u_free = force
      call band_solve(factor, u_free)
      u = u_free
      if (contacts%count == 0) return
      if (present(contact_method)) then
         call projector%setup(stiffness, factor, contacts, contact_regime, contact_method)
      else
         call projector%setup(stiffness, factor, contacts, contact_regime)
      end if
      if (present(max_iterations)) projector%max_iterations = max_iterations
      if (contacts%springs%count == 0) then
         call projector%project_admissible(u_free, u, reaction, iterations, stat, errmsg, force)
         return
      end if
      springs = contacts%springs
      springs%damping = 0
      call compliant%setup(springs, rule_mean, contact_regime, projector_method())
      ! p_j(U) = s_j g_j - s_j H_j U: q = s g, motion and force scales 1; the 'mean' rule with
      ! theta = 1 takes the force at the end, f(p(U)), with p0 unused
      call compliant%solve(springs, contacts, stiffness, projector, u_free, springs%sign*springs%level, &
                           springs%level*0, 1.0_dp, 1.0_dp, 1.0_dp, 1.0_dp, rigid_admissible, no_points, no_values, &
                           no_values, u, reaction, stat, errmsg)
      iterations = compliant%iterations
      if (stat /= 0) return
      do j = 1, springs%count
         reaction(springs%point(j)) = reaction(springs%point(j)) + springs%sign(j)*compliant%force(j)
      end do
   contains
      function projector_method() result(name)
         character(len=:), allocatable :: name
         name = 'newton'
         if (present(contact_method)) name = contact_method
      end function projector_method
   end subroutine solve_static
end module vibrobeam_static
