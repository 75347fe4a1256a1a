# Empty compiler generated dependencies file for fleetmap_server_core.
# This may be replaced when dependencies are built.
