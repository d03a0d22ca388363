!> Prints the table of every input variable (`scene_variables`), one line each:
!! group name kind extent max_length lowest highest. The scripts that check every
!! variable (bad_input/every_variable.sh) and the completeness of docs/input.md
!! (input/check_docs_complete.sh) read it, so a new variable is covered without editing
!! them.
program list_input_variables
   use vibrobeam_kinds, only: output_unit
   use vibrobeam_scene, only: scene_variables
   use vibrobeam_namelist_schema, only: namelist_variable, kind_real, kind_integer, kind_logical
   implicit none
   type(namelist_variable), allocatable :: table(:)
   integer :: k
   character(len=8) :: kind
   allocate (table, source=scene_variables())
   do k = 1, size(table)
      select case (table(k)%kind)
      case (kind_real)
         kind = 'real'
      case (kind_integer)
         kind = 'integer'
      case (kind_logical)
         kind = 'logical'
      case default
         kind = 'string'
      end select
      write (output_unit, '(a,1x,a,1x,a,1x,i0,1x,i0,2(1x,es12.5))') trim(table(k)%group), trim(table(k)%name), &
         trim(kind), table(k)%extent, table(k)%max_length, table(k)%lowest, table(k)%highest
   end do
end program list_input_variables
