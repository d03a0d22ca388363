# Empty compiler generated dependencies file for work_precision.
# This may be replaced when dependencies are built.
