# Empty compiler generated dependencies file for test_free_vibration_spectrum.
# This may be replaced when dependencies are built.
