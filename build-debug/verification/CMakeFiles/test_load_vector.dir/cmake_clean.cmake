file(REMOVE_RECURSE
  "CMakeFiles/test_load_vector.dir/unit/test_load_vector.f90.o"
  "test_load_vector"
  "test_load_vector.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang Fortran)
  include(CMakeFiles/test_load_vector.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
