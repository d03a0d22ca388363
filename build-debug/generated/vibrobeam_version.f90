!> Program version, filled in by CMake from project(VERSION).
module vibrobeam_version
   implicit none
   private
   public :: version_string
   character(len=*), parameter :: version_string = '0.1.0'  !! e.g. '0.1.0'
end module vibrobeam_version
