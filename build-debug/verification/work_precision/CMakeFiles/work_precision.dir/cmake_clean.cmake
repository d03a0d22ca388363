file(REMOVE_RECURSE
  "CMakeFiles/work_precision.dir/work_precision.f90.o"
  "work_precision"
  "work_precision.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang Fortran)
  include(CMakeFiles/work_precision.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
