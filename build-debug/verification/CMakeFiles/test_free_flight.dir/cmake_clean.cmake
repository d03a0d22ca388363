file(REMOVE_RECURSE
  "CMakeFiles/test_free_flight.dir/dynamics/test_free_flight.f90.o"
  "test_free_flight"
  "test_free_flight.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang Fortran)
  include(CMakeFiles/test_free_flight.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
