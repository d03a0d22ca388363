# Empty compiler generated dependencies file for check_modes_file.
# This may be replaced when dependencies are built.
