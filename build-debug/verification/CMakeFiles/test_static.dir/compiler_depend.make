# Empty compiler generated dependencies file for test_static.
# This may be replaced when dependencies are built.
