file(REMOVE_RECURSE
  "CMakeFiles/test_static.dir/dynamics/test_static.f90.o"
  "test_static"
  "test_static.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang Fortran)
  include(CMakeFiles/test_static.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
