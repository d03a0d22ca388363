file(REMOVE_RECURSE
  "CMakeFiles/test_contact_projection.dir/unit/test_contact_projection.f90.o"
  "test_contact_projection"
  "test_contact_projection.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang Fortran)
  include(CMakeFiles/test_contact_projection.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
