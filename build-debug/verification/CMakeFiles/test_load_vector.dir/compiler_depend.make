# Empty compiler generated dependencies file for test_load_vector.
# This may be replaced when dependencies are built.
