!> &initial velocity = 'rotation' and 'profile' against closed forms (docs/input.md,
!! "&initial"; theory §1, "Initial data"):
!! - rotation omega about the left end, Hermite: every nodal value is omega x_i and every
!!   rotation rate omega, bitwise (the same product the closed form is);
!! - rotation, B-splines: v = omega x is a cubic spline, whose coefficients are omega times
!!   the Greville abscissae (t_{j+1} + t_{j+2} + t_{j+3})/3 (Marsden's identity, de Boor,
!!   "A practical guide to splines", IX (41)); the computed ones within the round-off
!!   bound of the banded solve (below);
!! - a profile file (0, 0), (L, omega L) is the rotation, to the round-off of the table's
!!   interpolation (Hermite: gamma_5 |omega| L in a value, gamma_2 |omega| in a slope;
!!   B-splines: that perturbation of the data carried through |A^-1|);
!! - a constant profile is 'uniform' bitwise on Hermite elements (values v, slopes 0).
!! Pinned-free and free-free beams, N = 1, 7, 10. The checks fail when the rotation's
!! slope is dropped (B-splines miss omega x by O(omega h)) or a node's value is shifted.
program test_initial_velocity
   use vibrobeam_kinds, only: dp
   use vibrobeam_lapack, only: dgetrf
   use vibrobeam_model, only: beam_model, build_model, point_row, node_row
   use vibrobeam_boundary, only: boundary_conditions, end_pinned, end_free, end_clamped
   use vibrobeam_initial_state, only: initial_settings, initial_velocity, read_velocity_profile
   use vibrobeam_table_file, only: linear_table
   use vibrobeam_roundoff_bounds, only: gamma_n
   use vibrobeam_static_bounds, only: dense_inverse, permuted_lu_times
   use vibrobeam_test_support, only: test_counter, same_bits
   implicit none
   real(dp), parameter :: length = 0.783_dp, omega = -3.8_dp
   character(len=*), parameter :: file = 'test_initial_velocity_profile.dat'
   type(test_counter) :: t
   integer, parameter :: meshes(3) = [1, 7, 10]
   character(len=7), parameter :: bases(2) = ['hermite', 'bspline']
   integer :: b, k, e
   character(len=64) :: label
   do b = 1, 2
      do k = 1, size(meshes)
         do e = 1, 2
            write (label, '(a,a,i0,a)') trim(bases(b)), ' N=', meshes(k), merge(' pinned-free', ' free-free  ', e == 1)
            call check_rotation(trim(bases(b)), meshes(k), merge(end_pinned, end_free, e == 1), trim(label))
         end do
      end do
   end do
   call check_uniform()
   open (newunit=k, file=file)
   close (k, status='delete')
   call t%finish('test_initial_velocity')
contains
   !> Rotation and its profile on one mesh with the left end `left` and a free right end.
   subroutine check_rotation(basis, elements, left, label)
      character(len=*), intent(in) :: basis, label
      integer, intent(in) :: elements, left
      type(beam_model) :: model
      type(initial_settings) :: initial
      type(linear_table) :: profile
      real(dp), allocatable :: v(:), w(:), exact(:), a(:, :), factors(:, :), inverse(:, :), b_exact(:), bound(:)
      integer, allocatable :: pivots(:)
      real(dp) :: weights(4), knots_mean
      integer :: stat, i, j, n, dofs(4), info, unit, row
      character(len=256) :: errmsg
      call build_model(basis, elements, length, 2.0_dp, 3.0_dp, model, stat, errmsg, &
                       boundary=boundary_conditions(left, end_free))
      call t%check_true(label//' model', stat == 0, errmsg)
      if (stat /= 0) return
      initial%velocity = 'rotation'
      initial%velocity_amplitude = omega
      v = initial_velocity(initial, model)
      open (newunit=unit, file=file, status='replace')
      write (unit, '(a)') '# x (m), v (m/s)'
      write (unit, '(es24.16e3,1x,es24.16e3)') 0.0_dp, 0.0_dp, length, omega*length
      close (unit)
      initial%velocity = 'profile'
      initial%velocity_profile = file
      call read_velocity_profile(initial, length, profile, stat, errmsg)
      call t%check_true(label//' profile read', stat == 0, errmsg)
      if (stat /= 0) return
      w = initial_velocity(initial, model, profile)
      n = model%unknowns
      if (model%hermite) then
         do i = 0, elements
            if (model%unknown_of(2*i + 1) > 0) call t%check_true(label//' rotation: w_i = omega x_i bitwise', &
                                                                 same_bits(v(model%unknown_of(2*i + 1)), &
                                                                           omega*model%x(i + 1)))
            if (model%unknown_of(2*i + 2) > 0) call t%check_true(label//' rotation: theta_i = omega bitwise', &
                                                                 same_bits(v(model%unknown_of(2*i + 2)), omega))
         end do
         call t%check_close(label//' profile = rotation (values and slopes)', &
                            maxval(abs(w - v)/merge(abs(omega)*length, abs(omega), is_value(model))), &
                            0.0_dp, 1.0_dp, gamma_n(5))
         return
      end if
      ! B-splines: the unknowns are the coefficients c_j of the functions not held (the
      ! pinned end holds c_1 = 0, whose Greville abscissa is 0)
      allocate (exact(n))
      do j = 1, size(model%unknown_of)
         if (model%unknown_of(j) <= 0) cycle
         knots_mean = (model%knots(j + 1) + model%knots(j + 2) + model%knots(j + 3))/3
         exact(model%unknown_of(j)) = omega*knots_mean
      end do
      ! the conditions interpolate_field solves, as a dense matrix: the error of its banded
      ! LU solve is |dc| <= |A^-1| (gamma_{3n} P^T|L||U||c| + gamma_4 |b|) (Higham, Thm 9.4;
      ! |db|: the data omega x_i, omega and the Greville means, a few roundings each)
      allocate (a(n, n), b_exact(n), source=0.0_dp)
      row = 0
      if (left == end_free .or. left == end_pinned) then   ! both leave the rotation free: u_x(0)
         call point_row(model, 0.0_dp, dofs, weights, order=1)
         call add_row(a, b_exact, row, dofs, weights, omega)
      end if
      do i = 0, elements
         if (model%deflection_held(i)) cycle
         call node_row(model, i, dofs, weights)
         call add_row(a, b_exact, row, dofs, weights, omega*model%x(i + 1))
      end do
      call point_row(model, length, dofs, weights, order=1)
      call add_row(a, b_exact, row, dofs, weights, omega)
      call t%check_true(label//' one condition per unknown', row == n)
      factors = a
      allocate (pivots(n), bound(n))
      call dgetrf(n, n, factors, n, pivots, info)
      inverse = dense_inverse(a)
      bound(:) = matmul(abs(inverse), gamma_n(3*n)*permuted_lu_times(factors, pivots, abs(v)) + &
                     gamma_n(4)*abs(b_exact)) + gamma_n(4)*abs(exact)
      call t%check_close(label//' rotation: c_j = omega x Greville abscissa (error / bound)', &
                         maxval(abs(v - exact)/bound), 0.0_dp, 1.0_dp, 1.0_dp)
      ! the profile's data differ from the rotation's by gamma_4 |omega| L (values) and
      ! gamma_3 |omega| (slopes): through A^-1, and both solves' round-off
      bound(:) = 2*bound + matmul(abs(inverse), gamma_n(5)*abs(omega)*[(max(length, 1.0_dp), i=1, n)])
      call t%check_close(label//' profile = rotation (error / bound)', maxval(abs(w - v)/bound), 0.0_dp, 1.0_dp, 1.0_dp)
   end subroutine check_rotation

   !> The next row of the dense conditions `a` (its weights at the unknowns dofs) and of
   !! their right-hand side `b`; rows beyond the matrix are counted, not stored.
   subroutine add_row(a, b, row, dofs, weights, rhs)
      real(dp), intent(inout) :: a(:, :), b(:)
      integer, intent(inout) :: row
      integer, intent(in) :: dofs(4)
      real(dp), intent(in) :: weights(4), rhs
      integer :: c
      row = row + 1
      if (row > size(b)) return
      b(row) = rhs
      do c = 1, 4
         if (dofs(c) > 0) a(row, dofs(c)) = a(row, dofs(c)) + weights(c)
      end do
   end subroutine add_row

   !> Which Hermite unknowns of `model` are values (else slopes).
   function is_value(model) result(mask)
      type(beam_model), intent(in) :: model
      logical :: mask(model%unknowns)
      integer :: i
      mask = .true.
      do i = 0, model%elements
         if (model%unknown_of(2*i + 2) > 0) mask(model%unknown_of(2*i + 2)) = .false.
      end do
   end function is_value

   !> A constant profile is 'uniform' bitwise on Hermite elements (clamped-free, N = 7).
   subroutine check_uniform()
      type(beam_model) :: model
      type(initial_settings) :: initial
      type(linear_table) :: profile
      integer :: stat, unit
      character(len=256) :: errmsg
      call build_model('hermite', 7, length, 2.0_dp, 3.0_dp, model, stat, errmsg, &
                       boundary=boundary_conditions(end_clamped, end_free))
      open (newunit=unit, file=file, status='replace')
      write (unit, '(a)') '0 1.25', '0.3 1.25', '0.783 1.25'
      close (unit)
      initial%velocity = 'profile'
      initial%velocity_profile = file
      call read_velocity_profile(initial, length, profile, stat, errmsg)
      call t%check_true('constant profile read', stat == 0, errmsg)
      if (stat /= 0) return
      initial%velocity_amplitude = 1.25_dp
      associate (from_profile => initial_velocity(initial, model, profile))
         initial%velocity = 'uniform'
         call t%check_true('hermite: a constant profile is ''uniform'' bitwise', &
                           all(same_bits(from_profile, initial_velocity(initial, model))))
      end associate
   end subroutine check_uniform
end program test_initial_velocity
