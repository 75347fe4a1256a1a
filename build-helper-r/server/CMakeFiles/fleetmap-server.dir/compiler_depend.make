# Empty compiler generated dependencies file for fleetmap-server.
# This may be replaced when dependencies are built.
