file(REMOVE_RECURSE
  "CMakeFiles/benchmark_steps.dir/benchmark_steps.f90.o"
  "benchmark_steps"
  "benchmark_steps.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang Fortran)
  include(CMakeFiles/benchmark_steps.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
