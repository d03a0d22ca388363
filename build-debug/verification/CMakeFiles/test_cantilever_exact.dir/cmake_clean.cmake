file(REMOVE_RECURSE
  "CMakeFiles/test_cantilever_exact.dir/unit/test_cantilever_exact.f90.o"
  "test_cantilever_exact"
  "test_cantilever_exact.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang Fortran)
  include(CMakeFiles/test_cantilever_exact.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
