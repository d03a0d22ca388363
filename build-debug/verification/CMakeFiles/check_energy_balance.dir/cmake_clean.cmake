file(REMOVE_RECURSE
  "CMakeFiles/check_energy_balance.dir/dynamics/check_energy_balance.f90.o"
  "check_energy_balance"
  "check_energy_balance.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang Fortran)
  include(CMakeFiles/check_energy_balance.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
