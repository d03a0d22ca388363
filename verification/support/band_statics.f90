!> The statics of vibrobeam up to 0.x (before issue 23), kept for the benchmarks that compare
!! with it: U_free = K^-1 F by the band Cholesky of K, then the projection onto the admissible
!! set in the metric K (`contact_projector%project_admissible`). Its error grows like
!! cond(K) ~ N^4 (docs/method.md, "Statics"); the library's `solve_static` replaces it.
module vibrobeam_band_statics
   use vibrobeam_kinds, only: dp
   use vibrobeam_band, only: band_cholesky, band_factor, band_solve
   use vibrobeam_contact_projector, only: contact_projector
   use vibrobeam_problem, only: run_problem
   implicit none
   private
   public :: band_static_solve

contains

   !> The old static solve of a prepared scene with rigid obstacles: regime 'auto' |
   !! 'delassus' | 'band', method 'newton' | 'pivoting', at most `pivot_limit` pivots.
   subroutine band_static_solve(prepared, regime, method, pivot_limit, u, reaction, iterations, stat, errmsg)
      type(run_problem), intent(in) :: prepared
      character(len=*), intent(in) :: regime, method
      integer, intent(in) :: pivot_limit
      real(dp), intent(out) :: u(:), reaction(:)
      integer, intent(out) :: iterations, stat
      character(len=*), intent(out) :: errmsg
      type(band_cholesky) :: factor
      type(contact_projector) :: projector
      real(dp), allocatable :: u_free(:), force(:)
      iterations = 0
      reaction = 0
      force = prepared%loads%at(0.0_dp)
      call band_factor(prepared%model%stiffness, factor, stat, errmsg)
      if (stat /= 0) return
      u_free = force
      call band_solve(factor, u_free)
      u = u_free
      if (prepared%contacts%count == 0) return
      call projector%setup(prepared%model%stiffness, factor, prepared%contacts, regime, method)
      projector%max_iterations = pivot_limit
      call projector%project_admissible(u_free, u, reaction, iterations, stat, errmsg, force)
   end subroutine band_static_solve
end module vibrobeam_band_statics
