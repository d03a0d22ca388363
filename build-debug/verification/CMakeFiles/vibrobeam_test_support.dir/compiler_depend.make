# Empty compiler generated dependencies file for vibrobeam_test_support.
# This may be replaced when dependencies are built.
