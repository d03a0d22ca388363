!> Kinds and named constants shared by every vibrobeam module.
module vibrobeam_kinds
   use, intrinsic :: iso_fortran_env, only: dp => real64, int64, error_unit, output_unit
   implicit none
   private
   public :: dp, int64, error_unit, output_unit, pi

   !> Archimedes' constant to double precision.
   real(dp), parameter :: pi = 3.14159265358979323846264338327950288_dp
end module vibrobeam_kinds
