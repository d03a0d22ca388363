# Empty compiler generated dependencies file for self_convergence.
# This may be replaced when dependencies are built.
