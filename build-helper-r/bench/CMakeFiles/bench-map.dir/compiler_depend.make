# Empty compiler generated dependencies file for bench-map.
# This may be replaced when dependencies are built.
