file(REMOVE_RECURSE
  "CMakeFiles/test_free_vibration_spectrum.dir/dynamics/test_free_vibration_spectrum.f90.o"
  "test_free_vibration_spectrum"
  "test_free_vibration_spectrum.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang Fortran)
  include(CMakeFiles/test_free_vibration_spectrum.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
