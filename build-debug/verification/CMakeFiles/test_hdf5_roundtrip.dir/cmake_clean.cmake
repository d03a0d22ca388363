file(REMOVE_RECURSE
  "CMakeFiles/test_hdf5_roundtrip.dir/unit/test_hdf5_roundtrip.f90.o"
  "test_hdf5_roundtrip"
  "test_hdf5_roundtrip.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang Fortran)
  include(CMakeFiles/test_hdf5_roundtrip.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
