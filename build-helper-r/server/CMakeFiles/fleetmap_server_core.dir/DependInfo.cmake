
# Consider dependencies only in project.
set(CMAKE_DEPENDS_IN_PROJECT_ONLY OFF)

# The set of languages for which implicit dependencies are needed:
set(CMAKE_DEPENDS_LANGUAGES
  )

# The set of dependency files which are needed:
set(CMAKE_DEPENDS_DEPENDENCY_FILES
  "/work/main/server/handlers/alive.cpp" "server/CMakeFiles/fleetmap_server_core.dir/handlers/alive.cpp.o" "gcc" "server/CMakeFiles/fleetmap_server_core.dir/handlers/alive.cpp.o.d"
  "/work/main/server/handlers/get_map.cpp" "server/CMakeFiles/fleetmap_server_core.dir/handlers/get_map.cpp.o" "gcc" "server/CMakeFiles/fleetmap_server_core.dir/handlers/get_map.cpp.o.d"
  "/work/main/server/handlers/get_path.cpp" "server/CMakeFiles/fleetmap_server_core.dir/handlers/get_path.cpp.o" "gcc" "server/CMakeFiles/fleetmap_server_core.dir/handlers/get_path.cpp.o.d"
  "/work/main/server/handlers/get_pos_end.cpp" "server/CMakeFiles/fleetmap_server_core.dir/handlers/get_pos_end.cpp.o" "gcc" "server/CMakeFiles/fleetmap_server_core.dir/handlers/get_pos_end.cpp.o.d"
  "/work/main/server/handlers/get_pos_ini.cpp" "server/CMakeFiles/fleetmap_server_core.dir/handlers/get_pos_ini.cpp.o" "gcc" "server/CMakeFiles/fleetmap_server_core.dir/handlers/get_pos_ini.cpp.o.d"
  "/work/main/server/handlers/handler.cpp" "server/CMakeFiles/fleetmap_server_core.dir/handlers/handler.cpp.o" "gcc" "server/CMakeFiles/fleetmap_server_core.dir/handlers/handler.cpp.o.d"
  "/work/main/server/handlers/op_ack.cpp" "server/CMakeFiles/fleetmap_server_core.dir/handlers/op_ack.cpp.o" "gcc" "server/CMakeFiles/fleetmap_server_core.dir/handlers/op_ack.cpp.o.d"
  "/work/main/server/handlers/ready.cpp" "server/CMakeFiles/fleetmap_server_core.dir/handlers/ready.cpp.o" "gcc" "server/CMakeFiles/fleetmap_server_core.dir/handlers/ready.cpp.o.d"
  "/work/main/server/handlers/send_gps.cpp" "server/CMakeFiles/fleetmap_server_core.dir/handlers/send_gps.cpp.o" "gcc" "server/CMakeFiles/fleetmap_server_core.dir/handlers/send_gps.cpp.o.d"
  "/work/main/server/handlers/send_image.cpp" "server/CMakeFiles/fleetmap_server_core.dir/handlers/send_image.cpp.o" "gcc" "server/CMakeFiles/fleetmap_server_core.dir/handlers/send_image.cpp.o.d"
  "/work/main/server/handlers/send_pos.cpp" "server/CMakeFiles/fleetmap_server_core.dir/handlers/send_pos.cpp.o" "gcc" "server/CMakeFiles/fleetmap_server_core.dir/handlers/send_pos.cpp.o.d"
  "/work/main/server/handlers/set_object.cpp" "server/CMakeFiles/fleetmap_server_core.dir/handlers/set_object.cpp.o" "gcc" "server/CMakeFiles/fleetmap_server_core.dir/handlers/set_object.cpp.o.d"
  "/work/main/server/handlers/stopped.cpp" "server/CMakeFiles/fleetmap_server_core.dir/handlers/stopped.cpp.o" "gcc" "server/CMakeFiles/fleetmap_server_core.dir/handlers/stopped.cpp.o.d"
  "/work/main/server/map_cache.cpp" "server/CMakeFiles/fleetmap_server_core.dir/map_cache.cpp.o" "gcc" "server/CMakeFiles/fleetmap_server_core.dir/map_cache.cpp.o.d"
  "/work/main/server/request_loop.cpp" "server/CMakeFiles/fleetmap_server_core.dir/request_loop.cpp.o" "gcc" "server/CMakeFiles/fleetmap_server_core.dir/request_loop.cpp.o.d"
  "/work/main/server/server_config.cpp" "server/CMakeFiles/fleetmap_server_core.dir/server_config.cpp.o" "gcc" "server/CMakeFiles/fleetmap_server_core.dir/server_config.cpp.o.d"
  )

# Targets to which this target links.
set(CMAKE_TARGET_LINKED_INFO_FILES
  "/work/main/build-helper-r/protocol/CMakeFiles/fleetmap_protocol.dir/DependInfo.cmake"
  "/work/main/build-helper-r/common/CMakeFiles/fleetmap_common.dir/DependInfo.cmake"
  )

# Fortran module output directory.
set(CMAKE_Fortran_TARGET_MODULE_DIR "")
