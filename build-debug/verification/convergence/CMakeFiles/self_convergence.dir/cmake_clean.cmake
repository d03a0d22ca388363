file(REMOVE_RECURSE
  "CMakeFiles/self_convergence.dir/self_convergence.f90.o"
  "self_convergence"
  "self_convergence.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang Fortran)
  include(CMakeFiles/self_convergence.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
