# Empty compiler generated dependencies file for fleetmap_protocol.
# This may be replaced when dependencies are built.
