file(REMOVE_RECURSE
  "CMakeFiles/test_modes_convergence.dir/modes/test_modes_convergence.f90.o"
  "test_modes_convergence"
  "test_modes_convergence.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang Fortran)
  include(CMakeFiles/test_modes_convergence.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
