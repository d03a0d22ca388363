# Empty compiler generated dependencies file for test_bspline_modes.
# This may be replaced when dependencies are built.
