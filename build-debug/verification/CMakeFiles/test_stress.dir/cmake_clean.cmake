file(REMOVE_RECURSE
  "CMakeFiles/test_stress.dir/stress/test_stress.f90.o"
  "test_stress"
  "test_stress.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang Fortran)
  include(CMakeFiles/test_stress.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
