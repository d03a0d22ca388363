# Empty compiler generated dependencies file for test_cantilever_exact.
# This may be replaced when dependencies are built.
