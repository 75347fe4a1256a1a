file(REMOVE_RECURSE
  "../bin/fleetmap-server"
  "../bin/fleetmap-server.pdb"
  "CMakeFiles/fleetmap-server.dir/server_main.cpp.o"
  "CMakeFiles/fleetmap-server.dir/server_main.cpp.o.d"
)

# Per-language clean rules from dependency scanning.
foreach(lang CXX)
  include(CMakeFiles/fleetmap-server.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
