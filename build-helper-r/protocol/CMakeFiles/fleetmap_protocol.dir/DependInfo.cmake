
# Consider dependencies only in project.
set(CMAKE_DEPENDS_IN_PROJECT_ONLY OFF)

# The set of languages for which implicit dependencies are needed:
set(CMAKE_DEPENDS_LANGUAGES
  )

# The set of dependency files which are needed:
set(CMAKE_DEPENDS_DEPENDENCY_FILES
  "/work/main/protocol/connection.cpp" "protocol/CMakeFiles/fleetmap_protocol.dir/connection.cpp.o" "gcc" "protocol/CMakeFiles/fleetmap_protocol.dir/connection.cpp.o.d"
  "/work/main/protocol/db_settings.cpp" "protocol/CMakeFiles/fleetmap_protocol.dir/db_settings.cpp.o" "gcc" "protocol/CMakeFiles/fleetmap_protocol.dir/db_settings.cpp.o.d"
  "/work/main/protocol/fleet_store.cpp" "protocol/CMakeFiles/fleetmap_protocol.dir/fleet_store.cpp.o" "gcc" "protocol/CMakeFiles/fleetmap_protocol.dir/fleet_store.cpp.o.d"
  "/work/main/protocol/map_codec.cpp" "protocol/CMakeFiles/fleetmap_protocol.dir/map_codec.cpp.o" "gcc" "protocol/CMakeFiles/fleetmap_protocol.dir/map_codec.cpp.o.d"
  "/work/main/protocol/map_store.cpp" "protocol/CMakeFiles/fleetmap_protocol.dir/map_store.cpp.o" "gcc" "protocol/CMakeFiles/fleetmap_protocol.dir/map_store.cpp.o.d"
  "/work/main/protocol/ops.cpp" "protocol/CMakeFiles/fleetmap_protocol.dir/ops.cpp.o" "gcc" "protocol/CMakeFiles/fleetmap_protocol.dir/ops.cpp.o.d"
  "/work/main/protocol/params.cpp" "protocol/CMakeFiles/fleetmap_protocol.dir/params.cpp.o" "gcc" "protocol/CMakeFiles/fleetmap_protocol.dir/params.cpp.o.d"
  "/work/main/protocol/request_queue.cpp" "protocol/CMakeFiles/fleetmap_protocol.dir/request_queue.cpp.o" "gcc" "protocol/CMakeFiles/fleetmap_protocol.dir/request_queue.cpp.o.d"
  "/work/main/protocol/robot_store.cpp" "protocol/CMakeFiles/fleetmap_protocol.dir/robot_store.cpp.o" "gcc" "protocol/CMakeFiles/fleetmap_protocol.dir/robot_store.cpp.o.d"
  )

# Targets to which this target links.
set(CMAKE_TARGET_LINKED_INFO_FILES
  "/work/main/build-helper-r/common/CMakeFiles/fleetmap_common.dir/DependInfo.cmake"
  )

# Fortran module output directory.
set(CMAKE_Fortran_TARGET_MODULE_DIR "")
