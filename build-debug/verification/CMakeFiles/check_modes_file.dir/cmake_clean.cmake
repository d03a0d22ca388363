file(REMOVE_RECURSE
  "CMakeFiles/check_modes_file.dir/modes/check_modes_file.f90.o"
  "check_modes_file"
  "check_modes_file.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang Fortran)
  include(CMakeFiles/check_modes_file.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
