# Empty compiler generated dependencies file for test_lcp.
# This may be replaced when dependencies are built.
