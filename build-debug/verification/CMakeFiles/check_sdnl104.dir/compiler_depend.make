# Empty compiler generated dependencies file for check_sdnl104.
# This may be replaced when dependencies are built.
