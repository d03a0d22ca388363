!> The load profile of the Siconos benchmark's scene (a module procedure, so that it can be
!! passed to load_vector).
module siconos_benchmark_profile
   use vibrobeam_kinds, only: dp
   implicit none
   private
   public :: unit_load
contains
   !> q(x) = 1 (the scene's load is `&load distributed` times this).
   pure function unit_load(x) result(value)
      real(dp), intent(in) :: x
      real(dp) :: value
      value = 1 + 0*x
   end function unit_load
end module siconos_benchmark_profile
