# Remove fortran modules provided by this target.
FILE(REMOVE
  "../modules/load_profiles.mod"
  "../modules/LOAD_PROFILES.mod"
  "CMakeFiles/test_load_vector.dir/load_profiles.mod.stamp"
  )
