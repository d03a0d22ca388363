file(REMOVE_RECURSE
  "CMakeFiles/test_first_impact.dir/dynamics/test_first_impact.f90.o"
  "test_first_impact"
  "test_first_impact.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang Fortran)
  include(CMakeFiles/test_first_impact.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
