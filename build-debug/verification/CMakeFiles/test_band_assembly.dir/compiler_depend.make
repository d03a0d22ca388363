# Empty compiler generated dependencies file for test_band_assembly.
# This may be replaced when dependencies are built.
