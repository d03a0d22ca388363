!> Damping per mode (docs/theory.md §1, "Damping"; docs/method.md, "Damping per mode";
!! &beam modal_damping, modal_damping_ratios): each of the first K modes of the linear
!! model gets its own ratio zeta_k, the higher modes keep the Rayleigh damping alone.
!!
!! With Phi the first K modes, M-orthonormal (Phi^T M Phi = I), the damping matrix is
!!
!!     C = a M + b K + Y diag(c) Y^T,   Y = M Phi,   c_k = 2 zeta_k omega_k - a - b omega_k^2,
!!
!! so that Phi^T C Phi = diag(2 zeta_k omega_k) and C phi = (a M + b K) phi for every mode
!! M-orthogonal to Phi. The low-rank part costs 4 J K operations per product and is taken
!! explicitly by the steppers (at V^n), so that W keeps its band and the contact solvers
!! their metric; it is stable while c_k dt <= 1 (checked: `build_modal_damping` refuses a
!! mode the time step does not resolve). A rigid-body mode (omega = 0) has no ratio: it
!! keeps the Rayleigh damping.
module vibrobeam_modal_damping
   use vibrobeam_kinds, only: dp
   use vibrobeam_status, only: stat_failure
   use vibrobeam_text, only: integer_text, real_text
   use vibrobeam_schema_visitor, only: is_unset
   use vibrobeam_model, only: beam_model
   use vibrobeam_band, only: band_matvec
   use vibrobeam_modes, only: compute_modes
   implicit none
   private
   public :: build_modal_damping, max_damped_modes

   integer, parameter :: max_damped_modes = 100   !! most modes with a ratio of their own

contains

   !> Y and c (module documentation) of `model`: K is the last mode whose ratio `ratios` gives
   !! (unset elements: not given) and, with `every` > 0 (a ratio for every mode), every mode
   !! up to `cutoff` (rad/s), at most max_damped_modes and J - 1. stat = stat_failure with a
   !! message naming the input when a mode's rate c_k dt exceeds 1.
   subroutine build_modal_damping(model, every, ratios, cutoff, rayleigh_mass, rayleigh_stiffness, dt, forces, rates, &
                                  stat, errmsg)
      type(beam_model), intent(in) :: model
      real(dp), intent(in) :: every                    !! zeta of every mode (0: none)
      real(dp), intent(in) :: ratios(:)                !! zeta_k of mode k (unset: `every`)
      real(dp), intent(in) :: cutoff                   !! rad/s: with every > 0, the modes below it
      real(dp), intent(in) :: rayleigh_mass, rayleigh_stiffness   !! a (1/s), b (s)
      real(dp), intent(in) :: dt                       !! time step (s)
      real(dp), allocatable, intent(out) :: forces(:,:)   !! Y = M Phi (J x K)
      real(dp), allocatable, intent(out) :: rates(:)      !! c_k (1/s)
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      real(dp), allocatable :: omega(:), shapes(:,:), vectors(:,:)
      real(dp) :: zeta, norm
      integer :: given, kept, most, k
      stat = 0
      errmsg = ''
      most = min(max_damped_modes, size(ratios), model%unknowns - 1)
      given = 0
      do k = 1, size(ratios)
         if (.not. is_unset(ratios(k))) given = k
      end do
      kept = min(given, most)
      if (every > 0) kept = max(kept, min(most, 8))
      allocate (forces(model%unknowns, 0), rates(0))
      if (kept == 0) return
      do
         call compute_modes(model, kept, omega, shapes, vectors, stat, errmsg)
         if (stat /= 0) then
            errmsg = '&beam modal damping: '//trim(errmsg)
            return
         end if
         if (.not. every > 0 .or. kept == most .or. omega(kept) > cutoff) exit
         kept = min(most, 2*kept)
      end do
      if (every > 0) kept = max(min(given, most), count_below(omega, cutoff))
      deallocate (forces, rates)
      allocate (forces(model%unknowns, kept), rates(kept))
      do k = 1, kept
         zeta = every
         if (k <= size(ratios)) then
            if (.not. is_unset(ratios(k))) zeta = ratios(k)
         end if
         call band_matvec(model%mass, vectors(:, k), forces(:, k))
         norm = sqrt(dot_product(vectors(:, k), forces(:, k)))
         forces(:, k) = forces(:, k)/norm
         rates(k) = 0
         if (omega(k) > 0) rates(k) = 2*zeta*omega(k) - rayleigh_mass - rayleigh_stiffness*omega(k)**2
         if (abs(rates(k))*dt > 1) then
            stat = stat_failure
            if (k <= size(ratios)) then
               if (.not. is_unset(ratios(k))) then
                  errmsg = '&beam modal_damping_ratios('//integer_text(k)//') = '//real_text(zeta)
               else
                  errmsg = '&beam modal_damping = '//real_text(zeta)//' (mode '//integer_text(k)//')'
               end if
            end if
            errmsg = trim(errmsg)//': mode '//integer_text(k)//' (omega = '//real_text(omega(k))// &
                     ' rad/s) is damped explicitly, and its rate '//real_text(abs(rates(k)))//' 1/s times &time dt = '// &
                     real_text(dt)//' s exceeds 1; lower dt, or give that mode no ratio'
            return
         end if
      end do
   contains
      pure integer function count_below(values, limit)
         real(dp), intent(in) :: values(:), limit
         count_below = count(values <= limit)
      end function count_below
   end subroutine build_modal_damping
end module vibrobeam_modal_damping
