file(REMOVE_RECURSE
  "CMakeFiles/test_bspline_basis.dir/unit/test_bspline_basis.f90.o"
  "test_bspline_basis"
  "test_bspline_basis.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang Fortran)
  include(CMakeFiles/test_bspline_basis.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
