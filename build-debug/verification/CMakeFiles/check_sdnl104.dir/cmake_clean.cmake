file(REMOVE_RECURSE
  "CMakeFiles/check_sdnl104.dir/published/check_sdnl104.f90.o"
  "check_sdnl104"
  "check_sdnl104.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang Fortran)
  include(CMakeFiles/check_sdnl104.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
