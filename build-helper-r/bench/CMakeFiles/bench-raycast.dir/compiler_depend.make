# Empty compiler generated dependencies file for bench-raycast.
# This may be replaced when dependencies are built.
