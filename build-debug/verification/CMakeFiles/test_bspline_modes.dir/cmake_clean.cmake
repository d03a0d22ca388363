file(REMOVE_RECURSE
  "CMakeFiles/test_bspline_modes.dir/modes/test_bspline_modes.f90.o"
  "test_bspline_modes"
  "test_bspline_modes.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang Fortran)
  include(CMakeFiles/test_bspline_modes.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
