file(REMOVE_RECURSE
  "CMakeFiles/test_lcp.dir/unit/test_lcp.f90.o"
  "test_lcp"
  "test_lcp.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang Fortran)
  include(CMakeFiles/test_lcp.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
