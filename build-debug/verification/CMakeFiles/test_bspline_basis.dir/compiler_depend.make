# Empty compiler generated dependencies file for test_bspline_basis.
# This may be replaced when dependencies are built.
