# Empty compiler generated dependencies file for vibrobeam_lib.
# This may be replaced when dependencies are built.
