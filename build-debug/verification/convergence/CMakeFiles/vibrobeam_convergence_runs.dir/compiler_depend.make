# Empty compiler generated dependencies file for vibrobeam_convergence_runs.
# This may be replaced when dependencies are built.
