file(REMOVE_RECURSE
  "CMakeFiles/vibrobeam.dir/src/app/vibrobeam_main.f90.o"
  "vibrobeam"
  "vibrobeam.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang Fortran)
  include(CMakeFiles/vibrobeam.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
