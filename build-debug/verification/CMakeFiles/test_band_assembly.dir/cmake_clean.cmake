file(REMOVE_RECURSE
  "CMakeFiles/test_band_assembly.dir/unit/test_band_assembly.f90.o"
  "test_band_assembly"
  "test_band_assembly.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang Fortran)
  include(CMakeFiles/test_band_assembly.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
