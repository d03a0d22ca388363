# Empty compiler generated dependencies file for test_free_flight.
# This may be replaced when dependencies are built.
