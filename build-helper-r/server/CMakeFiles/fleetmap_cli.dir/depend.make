# Empty dependencies file for fleetmap_cli.
# This may be replaced when dependencies are built.
