# Empty dependencies file for fleetmap_common.
# This may be replaced when dependencies are built.
