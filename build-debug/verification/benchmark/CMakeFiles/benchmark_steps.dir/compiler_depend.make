# Empty compiler generated dependencies file for benchmark_steps.
# This may be replaced when dependencies are built.
