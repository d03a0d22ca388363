# Remove fortran modules provided by this target.
FILE(REMOVE
  "../modules/vibrobeam_test_support.mod"
  "../modules/VIBROBEAM_TEST_SUPPORT.mod"
  "CMakeFiles/vibrobeam_test_support.dir/vibrobeam_test_support.mod.stamp"
  )
