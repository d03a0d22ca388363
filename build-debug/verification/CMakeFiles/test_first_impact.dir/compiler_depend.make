# Empty compiler generated dependencies file for test_first_impact.
# This may be replaced when dependencies are built.
