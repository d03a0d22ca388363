# Empty compiler generated dependencies file for vibrobeam.
# This may be replaced when dependencies are built.
