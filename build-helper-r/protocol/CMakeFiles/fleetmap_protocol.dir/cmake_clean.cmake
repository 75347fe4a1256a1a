file(REMOVE_RECURSE
  "CMakeFiles/fleetmap_protocol.dir/connection.cpp.o"
  "CMakeFiles/fleetmap_protocol.dir/connection.cpp.o.d"
  "CMakeFiles/fleetmap_protocol.dir/db_settings.cpp.o"
  "CMakeFiles/fleetmap_protocol.dir/db_settings.cpp.o.d"
  "CMakeFiles/fleetmap_protocol.dir/fleet_store.cpp.o"
  "CMakeFiles/fleetmap_protocol.dir/fleet_store.cpp.o.d"
  "CMakeFiles/fleetmap_protocol.dir/map_codec.cpp.o"
  "CMakeFiles/fleetmap_protocol.dir/map_codec.cpp.o.d"
  "CMakeFiles/fleetmap_protocol.dir/map_store.cpp.o"
  "CMakeFiles/fleetmap_protocol.dir/map_store.cpp.o.d"
  "CMakeFiles/fleetmap_protocol.dir/ops.cpp.o"
  "CMakeFiles/fleetmap_protocol.dir/ops.cpp.o.d"
  "CMakeFiles/fleetmap_protocol.dir/params.cpp.o"
  "CMakeFiles/fleetmap_protocol.dir/params.cpp.o.d"
  "CMakeFiles/fleetmap_protocol.dir/request_queue.cpp.o"
  "CMakeFiles/fleetmap_protocol.dir/request_queue.cpp.o.d"
  "CMakeFiles/fleetmap_protocol.dir/robot_store.cpp.o"
  "CMakeFiles/fleetmap_protocol.dir/robot_store.cpp.o.d"
  "libfleetmap_protocol.a"
  "libfleetmap_protocol.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang CXX)
  include(CMakeFiles/fleetmap_protocol.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
