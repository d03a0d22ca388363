!> Independent references for linear responses (tests of &forces and of the random
!! response, docs/theory.md section 9): the transfer function of the discrete model, by
!! dense complex LU (LAPACK zgesv) on the matrices expanded from band storage, for the
!! semi-discrete system (s = i omega) and for the velocity scheme's theta-method (s = the
!! scheme's own discrete s of z = exp(i omega dt), below); the load vector of a uniform
!! load over a segment by Simpson's rule (the library uses Gauss' rule).
module vibrobeam_linear_response
   use vibrobeam_kinds, only: dp
   use vibrobeam_band, only: symmetric_band, band_to_dense
   use vibrobeam_model, only: beam_model, point_row
   implicit none
   private
   public :: dense_transfer, theta_frequency, simpson_load_vector

   interface
      subroutine zgesv(n, nrhs, a, lda, ipiv, b, ldb, info)
         import :: dp
         integer, intent(in) :: n, nrhs, lda, ldb
         complex(dp), intent(inout) :: a(lda, *), b(ldb, *)
         integer, intent(out) :: ipiv(*), info
      end subroutine zgesv
   end interface

contains

   !> x = (s^2 M + s C + K)^-1 f, C = a M + b K + extra (extra: a dense damping, optional),
   !! by a dense LU: the response of M U'' + C U' + K U = f e^{s t} (s = i omega), or of
   !! the scheme at its discrete s (`theta_frequency`).
   function dense_transfer(mass, stiffness, rayleigh_mass, rayleigh_stiffness, s, f, extra) result(x)
      type(symmetric_band), intent(in) :: mass, stiffness
      real(dp), intent(in) :: rayleigh_mass, rayleigh_stiffness
      complex(dp), intent(in) :: s
      complex(dp), intent(in) :: f(:)
      real(dp), intent(in), optional :: extra(:, :)
      complex(dp) :: x(size(f))
      real(dp) :: m(size(f), size(f)), k(size(f), size(f))
      complex(dp) :: a(size(f), size(f)), b(size(f), 1)
      integer :: n, info, pivots(size(f))
      n = size(f)
      m = band_to_dense(mass)
      k = band_to_dense(stiffness)
      a = s**2*m + s*(rayleigh_mass*m + rayleigh_stiffness*k) + k
      if (present(extra)) a = a + s*extra
      b(:, 1) = f
      call zgesv(n, 1, a, n, pivots, b, n, info)
      if (info /= 0) error stop 'dense_transfer: singular matrix'
      x = b(:, 1)
   end function dense_transfer

   !> The theta-method's discrete Laplace variable at angular frequency omega (rad/s):
   !! with z = exp(i omega dt), the velocity scheme (theory §3) maps a sampled
   !! F_n = F z^n to U_n = (s^2 M + s C + K)^-1 F z^n with s = (z - 1)/(dt (theta z + 1 - theta))
   !! (from M (z - 1) V = dt (theta z + 1 - theta)(F - K U - C V), (z - 1) U =
   !! dt (theta z + 1 - theta) V). For theta = 1/2, s = (2i/dt) tan(omega dt/2).
   pure complex(dp) function theta_frequency(omega, dt, theta) result(s)
      real(dp), intent(in) :: omega, dt, theta
      complex(dp) :: z
      z = exp(cmplx(0.0_dp, omega*dt, dp))
      s = (z - 1)/(dt*(theta*z + 1 - theta))
   end function theta_frequency

   !> The integral of phi_j over [a, b] by Simpson's rule on each element's part (exact
   !! for the cubic shape functions).
   function simpson_load_vector(model, a, b) result(f)
      type(beam_model), intent(in) :: model
      real(dp), intent(in) :: a, b
      real(dp) :: f(model%unknowns), weights(4), lo, hi, x, simpson(3)
      integer :: dofs(4), e, i, j
      f = 0
      simpson = [1.0_dp, 4.0_dp, 1.0_dp]/6
      do e = 1, model%elements
         lo = max(a, model%x(e))
         hi = min(b, model%x(e + 1))
         if (hi <= lo) cycle
         do i = 0, 2
            x = lo + i*(hi - lo)/2
            ! the element's own shape functions, also at its ends
            call point_row(model, min(max(x, model%x(e) + 1e-14_dp*model%h), model%x(e + 1) - 1e-14_dp*model%h), &
                           dofs, weights)
            do j = 1, 4
               if (dofs(j) /= 0) f(dofs(j)) = f(dofs(j)) + simpson(i + 1)*(hi - lo)*weights(j)
            end do
         end do
      end do
   end function simpson_load_vector
end module vibrobeam_linear_response
