file(REMOVE_RECURSE
  "CMakeFiles/vibrobeam_convergence_runs.dir/convergence_runs.f90.o"
  "libvibrobeam_convergence_runs.a"
  "libvibrobeam_convergence_runs.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang Fortran)
  include(CMakeFiles/vibrobeam_convergence_runs.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
