file(REMOVE_RECURSE
  "CMakeFiles/fleetmap_cli.dir/cli_context.cpp.o"
  "CMakeFiles/fleetmap_cli.dir/cli_context.cpp.o.d"
  "CMakeFiles/fleetmap_cli.dir/map_commands.cpp.o"
  "CMakeFiles/fleetmap_cli.dir/map_commands.cpp.o.d"
  "CMakeFiles/fleetmap_cli.dir/robot_commands.cpp.o"
  "CMakeFiles/fleetmap_cli.dir/robot_commands.cpp.o.d"
  "libfleetmap_cli.a"
  "libfleetmap_cli.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang CXX)
  include(CMakeFiles/fleetmap_cli.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
