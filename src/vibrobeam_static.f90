!> Static equilibrium against the obstacles (SPEC §6 "Static contact", &analysis kind =
!! 'static' and &initial displacement = 'static'):
!!
!!     U = argmin 1/2 U^T K U - F^T U   subject to   g1(x_c) <= H_c U <= g2(x_c),
!!
!! i.e. the projection of U_free = K^-1 F onto the admissible set in the metric K
!! (`contact_projector%project_admissible`, the machinery of a contact step). Reactions
!! are the multipliers P_c (N; per unit mass when the beam is given by k2), positive
!! upwards.
module vibrobeam_static
   use vibrobeam_kinds, only: dp
   use vibrobeam_band, only: symmetric_band, band_cholesky, band_factor, band_solve
   use vibrobeam_contact_points, only: contact_set
   use vibrobeam_contact_solver, only: contact_projector
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
      call projector%project_admissible(u_free, u, reaction, iterations, stat, errmsg, force)
   end subroutine solve_static
end module vibrobeam_static
