file(REMOVE_RECURSE
  "libvibrobeam_test_support.a"
)
