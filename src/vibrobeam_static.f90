!> Static equilibrium against the obstacles (SPEC §6 "Static contact", &analysis kind =
!! 'static' and &initial displacement = 'static'):
!!
!!     U = argmin 1/2 U^T K U - F^T U   subject to   g1(x_c) <= H_c U <= g2(x_c),
!!
!! i.e. the projection of U_free = K^-1 F in the metric K (the same machinery as a contact
!! step, `vibrobeam_contact_solver`). Each contact point may bound from below and above;
!! the side that can be active is the one the current solution violates, so we start
!! from the points U_free violates and add (or switch the side of) every point a solution
!! still violates, until none does. Reactions are the multipliers P_c (N; per unit mass
!! when the beam is given by k2), positive upwards.
module vibrobeam_static
   use vibrobeam_kinds, only: dp
   use vibrobeam_band, only: symmetric_band, band_cholesky, band_factor, band_solve
   use vibrobeam_contact_points, only: contact_set, contact_value, no_bound
   use vibrobeam_contact_solver, only: contact_projector
   implicit none
   private
   public :: solve_static

contains

   subroutine solve_static(stiffness, contacts, force, contact_regime, u, reaction, iterations, stat, errmsg)
      type(symmetric_band), intent(in) :: stiffness
      type(contact_set), intent(in) :: contacts
      real(dp), intent(in) :: force(:)                 !! F (J)
      character(len=*), intent(in) :: contact_regime   !! 'auto' | 'delassus' | 'band'
      real(dp), intent(out) :: u(:)                    !! equilibrium (J)
      real(dp), intent(out) :: reaction(:)             !! (contacts%count) P_c, 0 if not in contact
      integer, intent(out) :: iterations, stat
      character(len=*), intent(out) :: errmsg
      type(band_cholesky) :: factor
      type(contact_projector) :: projector
      real(dp) :: u_free(size(force)), value, scale
      real(dp), allocatable :: signs(:), offsets(:), impulse(:)
      integer, allocatable :: side(:), active(:)
      integer :: c, round, solver_iterations, m
      logical :: changed
      iterations = 0
      reaction = 0
      call band_factor(stiffness, factor, stat, errmsg)
      if (stat /= 0) return
      u_free = force
      call band_solve(factor, u_free)
      u = u_free
      if (contacts%count == 0) return
      call projector%setup(stiffness, factor, contacts, contact_regime)
      allocate (side(contacts%count), source=0)   ! +1 below, -1 above, 0 not a candidate
      ! violations are judged relative to the size of the free solution and of the levels
      scale = maxval(abs(u_free)) + tiny(1.0_dp)
      do c = 1, contacts%count
         if (contacts%lower(c) > -no_bound) scale = max(scale, abs(contacts%lower(c)))
         if (contacts%upper(c) < no_bound) scale = max(scale, abs(contacts%upper(c)))
      end do
      do round = 1, 2*contacts%count + 1
         changed = .false.
         do c = 1, contacts%count
            value = contact_value(contacts, c, u)
            if (value < contacts%lower(c) - 1e-12_dp*scale .and. side(c) /= 1) then
               side(c) = 1
               changed = .true.
            else if (value > contacts%upper(c) + 1e-12_dp*scale .and. side(c) /= -1) then
               side(c) = -1
               changed = .true.
            end if
         end do
         if (.not. changed) return
         active = pack([(c, c=1, contacts%count)], side /= 0)
         m = size(active)
         signs = real(side(active), dp)
         offsets = merge(contacts%lower(active), contacts%upper(active), side(active) == 1)
         if (allocated(impulse)) deallocate (impulse)
         allocate (impulse(m))
         call projector%project(u_free, active, signs, offsets, u, impulse, solver_iterations, stat, errmsg)
         iterations = iterations + solver_iterations
         if (stat /= 0) return
         reaction = 0
         reaction(active) = impulse
      end do
      stat = 1
      errmsg = 'static contact: the candidate contact set did not settle'
   end subroutine solve_static
end module vibrobeam_static
