file(REMOVE_RECURSE
  "CMakeFiles/test_first_episode.dir/test_first_episode.f90.o"
  "test_first_episode"
  "test_first_episode.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang Fortran)
  include(CMakeFiles/test_first_episode.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
