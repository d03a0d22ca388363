!> Shared checks of the vibrobeam test programs: each check prints one line on failure
!! naming the quantity, its value, the reference and the tolerance; `finish` prints
!! 'NAME: N passed, M failed' and exits non-zero when anything failed, and the largest
!! ratio |value - reference| / allowed difference over the `check_close` calls (how much
!! room each tolerance leaves; the CI prints it for every library it runs on).
module vibrobeam_test_support
   use vibrobeam_kinds, only: dp, error_unit, output_unit
   use vibrobeam_scene, only: scene_type, validate_scene
   use vibrobeam_input, only: read_scene
   use vibrobeam_setup, only: prepared_scene, prepare_scene
   use vibrobeam_blas_threads, only: limit_blas_threads
   implicit none
   private
   public :: test_counter, read_test_scene, prepare_test_scene, fitted_order

   type, public :: test_counter
      integer :: passed = 0
      integer :: failed = 0
      real(dp) :: worst_ratio = 0                !! largest |value - reference| / allowed difference
      character(len=120) :: worst_check = ''     !! the check where it occurred
   contains
      procedure :: check_close     !! |value - reference| <= tolerance * max(|reference|, scale)
      procedure :: check_true
      procedure :: finish
   end type test_counter

contains

   subroutine check_close(self, name, value, reference, tolerance, scale)
      class(test_counter), intent(inout) :: self
      character(len=*), intent(in) :: name
      real(dp), intent(in) :: value, reference, tolerance
      real(dp), intent(in), optional :: scale   !! floor of the relative scale (default tiny)
      real(dp) :: size
      size = abs(reference)
      if (present(scale)) size = max(size, scale)
      if (tolerance*size > 0) then
         if (report_every_check()) write (output_unit, '(a,es10.3,a)') 'ratio ', &
            abs(value - reference)/(tolerance*size), ' '//name
         if (abs(value - reference)/(tolerance*size) >= self%worst_ratio) then
            self%worst_ratio = abs(value - reference)/(tolerance*size)
            self%worst_check = name
         end if
      end if
      if (abs(value - reference) <= tolerance*size) then
         self%passed = self%passed + 1
      else
         self%failed = self%failed + 1
         write (error_unit, '(a,es23.15,a,es23.15,a,es10.3,a,es10.3)') 'FAIL '//name//': value ', value, &
            ', reference ', reference, ', relative difference ', abs(value - reference)/max(size, tiny(size)), &
            ', tolerance ', tolerance
      end if
   end subroutine check_close

   !> VIBROBEAM_CHECK_RATIOS set: print the ratio of every check (for margin studies).
   logical function report_every_check()
      integer :: length
      call get_environment_variable('VIBROBEAM_CHECK_RATIOS', length=length)
      report_every_check = length > 0
   end function report_every_check

   subroutine check_true(self, name, condition, detail)
      class(test_counter), intent(inout) :: self
      character(len=*), intent(in) :: name
      logical, intent(in) :: condition
      character(len=*), intent(in), optional :: detail
      if (condition) then
         self%passed = self%passed + 1
      else
         self%failed = self%failed + 1
         if (present(detail)) then
            write (error_unit, '(a)') 'FAIL '//name//': '//detail
         else
            write (error_unit, '(a)') 'FAIL '//name
         end if
      end if
   end subroutine check_true

   subroutine finish(self, program_name)
      class(test_counter), intent(in) :: self
      character(len=*), intent(in) :: program_name
      if (len_trim(self%worst_check) > 0) write (output_unit, '(a,es10.3,a)') program_name// &
         ': largest |value - reference| / tolerance ', self%worst_ratio, ' ('//trim(self%worst_check)//')'
      write (output_unit, '(a,i0,a,i0,a)') program_name//': ', self%passed, ' passed, ', self%failed, ' failed'
      if (self%failed > 0) error stop 1
   end subroutine finish

   !> Least-squares slope of log(error) against log(1/N) over the points marked `use`: the
   !! observed order of convergence in h = L/N (0 when fewer than 2 points are used).
   pure function fitted_order(elements, error, use) result(slope)
      integer, intent(in) :: elements(:)     !! N of each point
      real(dp), intent(in) :: error(:)       !! error of each point (> 0 where used)
      logical, intent(in) :: use(:)
      real(dp) :: slope
      real(dp) :: x(size(error)), y(size(error))
      integer :: m
      x = log(1.0_dp/elements)
      y = log(max(min(error, 1.0_dp), tiny(1.0_dp)))
      m = count(use)
      slope = 0
      if (m >= 2) slope = (m*sum(x*y, use) - sum(x, use)*sum(y, use))/(m*sum(x*x, use) - sum(x, use)**2)
   end function fitted_order

   !> The scene of a verification namelist file; stops the test if it is not valid.
   function read_test_scene(path) result(scene)
      character(len=*), intent(in) :: path
      type(scene_type) :: scene
      integer :: stat
      character(len=512) :: errmsg
      call read_scene(path, scene, stat, errmsg)
      if (stat == 0) call validate_scene(scene, stat, errmsg)
      if (stat /= 0) then
         write (error_unit, '(a)') 'FAIL reading '//path//': '//trim(errmsg)
         error stop 1
      end if
   end function read_test_scene

   !> prepare_scene, stopping the test on failure; the BLAS thread policy of the program
   !! (`limit_blas_threads`) applies to every driver that steps a scene.
   subroutine prepare_test_scene(scene, prepared)
      type(scene_type), intent(in) :: scene
      type(prepared_scene), intent(out) :: prepared
      character(len=:), allocatable :: warnings
      integer :: stat
      character(len=512) :: errmsg
      call limit_blas_threads(warnings)
      if (len(warnings) > 0) write (error_unit, '(a)') 'warning: '//warnings
      warnings = ''
      call prepare_scene(scene, prepared, warnings, stat, errmsg)
      if (stat /= 0) then
         write (error_unit, '(a)') 'FAIL preparing the scene: '//trim(errmsg)
         error stop 1
      end if
   end subroutine prepare_test_scene
end module vibrobeam_test_support
