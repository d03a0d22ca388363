file(REMOVE_RECURSE
  "CMakeFiles/test_energy.dir/dynamics/test_energy.f90.o"
  "test_energy"
  "test_energy.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang Fortran)
  include(CMakeFiles/test_energy.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
