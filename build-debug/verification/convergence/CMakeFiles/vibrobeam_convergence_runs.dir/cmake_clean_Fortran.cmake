# Remove fortran modules provided by this target.
FILE(REMOVE
  "../../modules/vibrobeam_convergence_runs.mod"
  "../../modules/VIBROBEAM_CONVERGENCE_RUNS.mod"
  "CMakeFiles/vibrobeam_convergence_runs.dir/vibrobeam_convergence_runs.mod.stamp"
  )
