!> FFTW's Fortran 2003 interface (fftw3.f03) for the test programs that estimate densities
!! themselves: included in a module, whose parameters a program may leave unused (included
!! in a program, every unused one draws a warning in the Debug build).
module vibrobeam_test_fftw
   use, intrinsic :: iso_c_binding
   implicit none
   public
   include 'fftw3.f03'
end module vibrobeam_test_fftw
