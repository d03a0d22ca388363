!> Writes the mass and stiffness matrices, the load vector of a unit uniform load and the
!! tip unknown of vibrobeam's Hermite model (k2 = 1, L = 1) for the Siconos side-by-side
!! benchmark (REPORT.md beside this file), so that Siconos steps exactly vibrobeam's
!! discrete system.
!!
!! usage: export_model N FILE
!! FILE: line 1 "J kd tip" (tip: 1-based index of the tip displacement unknown), then the
!! lower band of M column by column (kd + 1 numbers per line, A(j + i, j) for i = 0..kd),
!! then the same for K, then F (one number per line). Numbers in es25.17 (round trip).
program export_model
   use vibrobeam_kinds, only: dp, error_unit
   use vibrobeam_model, only: beam_model, build_model, load_vector
   use siconos_benchmark_profile, only: unit_load
   implicit none
   type(beam_model) :: model
   character(len=256) :: argument, file
   character(len=256) :: errmsg
   real(dp), allocatable :: f(:)
   integer :: elements, stat, unit, j
   if (command_argument_count() /= 2) then
      write (error_unit, '(a)') 'usage: export_model N FILE'
      error stop 2
   end if
   call get_command_argument(1, argument)
   read (argument, *) elements
   call get_command_argument(2, file)
   call build_model('hermite', elements, 1.0_dp, 1.0_dp, 1.0_dp, model, stat, errmsg)
   if (stat /= 0) then
      write (error_unit, '(a)') trim(errmsg)
      error stop 1
   end if
   f = load_vector(model, unit_load)
   open (newunit=unit, file=trim(file), status='replace', action='write')
   write (unit, '(i0,1x,i0,1x,i0)') model%unknowns, model%mass%kd, model%unknowns - 1
   do j = 1, model%unknowns
      write (unit, '(*(es25.17))') model%mass%lower(:, j)
   end do
   do j = 1, model%unknowns
      write (unit, '(*(es25.17))') model%stiffness%lower(:, j)
   end do
   write (unit, '(es25.17)') f
   close (unit)
end program export_model
