file(REMOVE_RECURSE
  "CMakeFiles/test_spectrum.dir/unit/test_spectrum.f90.o"
  "test_spectrum"
  "test_spectrum.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang Fortran)
  include(CMakeFiles/test_spectrum.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
