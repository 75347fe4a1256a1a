# Empty dependencies file for fleetmap-robot.
# This may be replaced when dependencies are built.
