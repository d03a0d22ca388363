# Empty compiler generated dependencies file for test_hdf5_roundtrip.
# This may be replaced when dependencies are built.
