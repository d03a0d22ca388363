!> The supports hold the degrees of freedom they should (`vibrobeam_boundary`, used by
!! `build_model`): the lowest natural frequencies of the discrete beam on several pairs of
!! end supports, from the assembled band M and K by dense LAPACK (dsygv on the expanded
!! matrices, independent of the band routines and of the modes module), against the closed
!! forms of the continuum, omega_n = (beta_n L)^2 sqrt(EI/(rho S))/L^2 (Blevins, "Formulas
!! for natural frequency and mode shape", 1979, table 8-1): clamped-free 1.87510406871196,
!! 4.69409113297418; pinned-pinned n pi; clamped-clamped 4.73004074486270,
!! 7.85320462409584; clamped-pinned 3.92660231204792, 7.06858274562873; sliding-pinned
!! (sliding: rotation held, deflection free) (n - 1/2) pi, the modes cos((n - 1/2) pi x/L).
!! Both bases (a sliding end of B-splines ties c_2 to c_1, a change of basis of the model).
!!
!! Tolerance: the discretization error of cubic elements in omega_n is about
!! (beta_n h)^4/1440 relative (docs/method.md, "Natural modes"); with N = 40 and
!! beta_2 L < 8 that is below 4e-7 for Hermite (and of the same order for B-splines, whose
!! error constant is larger: measured below 3e-6); 1e-5 bounds both, far above the
!! round-off of a dense symmetric eigensolve of a 80 x 80 pencil (1e-12 relative).
program test_boundary_supports
   use vibrobeam_kinds, only: dp, pi
   use vibrobeam_model, only: beam_model, build_model
   use vibrobeam_boundary, only: boundary_conditions, end_clamped, end_pinned, end_sliding, end_free
   use vibrobeam_test_support, only: test_counter
   implicit none
   type(test_counter) :: t
   integer, parameter :: elements = 40
   real(dp), parameter :: length = 0.8_dp, rho_s = 2.5_dp, ei = 40.0_dp
   character(len=7), parameter :: bases(2) = ['hermite', 'bspline']
   integer :: b
   do b = 1, 2
      call check(bases(b), boundary_conditions(end_clamped, end_free), [1.87510406871196_dp, 4.69409113297418_dp])
      call check(bases(b), boundary_conditions(end_pinned, end_pinned), [pi, 2*pi])
      call check(bases(b), boundary_conditions(end_clamped, end_clamped), [4.73004074486270_dp, 7.85320462409584_dp])
      call check(bases(b), boundary_conditions(end_clamped, end_pinned), [3.92660231204792_dp, 7.06858274562873_dp])
      call check(bases(b), boundary_conditions(end_pinned, end_clamped), [3.92660231204792_dp, 7.06858274562873_dp])
   end do
   ! a sliding end (rotation held): sliding-pinned, beta L = (n - 1/2) pi
   call check('hermite', boundary_conditions(end_sliding, end_pinned), [0.5_dp*pi, 1.5_dp*pi])
   call check('bspline', boundary_conditions(end_sliding, end_pinned), [0.5_dp*pi, 1.5_dp*pi])
   call t%finish('test_boundary_supports')

contains

   subroutine check(basis, supports, beta_l)
      character(len=*), intent(in) :: basis
      type(boundary_conditions), intent(in) :: supports
      real(dp), intent(in) :: beta_l(:)
      type(beam_model) :: model
      integer :: stat, n
      character(len=256) :: errmsg
      real(dp), allocatable :: omega(:)
      call build_model(basis, elements, length, rho_s, ei, model, stat, errmsg, boundary=supports)
      call t%check_true(basis//' '//supports%name()//': the model is built', stat == 0, errmsg)
      if (stat /= 0) return
      omega = lowest_frequencies(model, size(beta_l))
      do n = 1, size(beta_l)
         call t%check_close(basis//' '//supports%name()//': omega_'//achar(48 + n)//' (rad/s)', omega(n), &
                            beta_l(n)**2*sqrt(ei/rho_s)/length**2, 1e-5_dp)
      end do
   end subroutine check

   !> The `count` lowest omega of K phi = omega^2 M phi: M and K expanded from band storage,
   !! then LAPACK dsygv (dense, generalized symmetric-definite).
   function lowest_frequencies(model, count) result(omega)
      type(beam_model), intent(in) :: model
      integer, intent(in) :: count
      real(dp) :: omega(count)
      real(dp) :: m(model%unknowns, model%unknowns), k(model%unknowns, model%unknowns), w(model%unknowns)
      real(dp), allocatable :: work(:)
      integer :: i, j, info, n
      interface
         subroutine dsygv(itype, jobz, uplo, n, a, lda, b, ldb, w, work, lwork, info)
            import :: dp
            integer, intent(in) :: itype, n, lda, ldb, lwork
            character(len=1), intent(in) :: jobz, uplo
            real(dp), intent(inout) :: a(lda, *), b(ldb, *)
            real(dp), intent(out) :: w(*), work(*)
            integer, intent(out) :: info
         end subroutine dsygv
      end interface
      n = model%unknowns
      m = 0
      k = 0
      do j = 1, n
         do i = j, min(n, j + model%mass%kd)
            m(i, j) = model%mass%lower(1 + i - j, j)
            m(j, i) = m(i, j)
            k(i, j) = model%stiffness%lower(1 + i - j, j)
            k(j, i) = k(i, j)
         end do
      end do
      allocate (work(64*n))
      call dsygv(1, 'N', 'L', n, k, n, m, n, w, work, size(work), info)
      if (info /= 0) error stop 'dsygv failed'
      omega = sqrt(max(w(1:count), 0.0_dp))
   end function lowest_frequencies
end program test_boundary_supports
