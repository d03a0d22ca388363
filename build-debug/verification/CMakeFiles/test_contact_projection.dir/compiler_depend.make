# Empty compiler generated dependencies file for test_contact_projection.
# This may be replaced when dependencies are built.
