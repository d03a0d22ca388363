# Empty compiler generated dependencies file for check_energy_balance.
# This may be replaced when dependencies are built.
