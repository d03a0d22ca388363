file(REMOVE_RECURSE
  "libvibrobeam_convergence_runs.a"
)
