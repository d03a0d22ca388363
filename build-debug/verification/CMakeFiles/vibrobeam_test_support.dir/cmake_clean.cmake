file(REMOVE_RECURSE
  "CMakeFiles/vibrobeam_test_support.dir/test_support.f90.o"
  "libvibrobeam_test_support.a"
  "libvibrobeam_test_support.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang Fortran)
  include(CMakeFiles/vibrobeam_test_support.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
