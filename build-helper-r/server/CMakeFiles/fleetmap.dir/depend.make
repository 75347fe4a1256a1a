# Empty dependencies file for fleetmap.
# This may be replaced when dependencies are built.
