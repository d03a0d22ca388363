file(REMOVE_RECURSE
  "libvibrobeam_lib.a"
)
