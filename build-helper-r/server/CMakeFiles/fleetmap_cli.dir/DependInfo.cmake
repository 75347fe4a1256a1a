
# Consider dependencies only in project.
set(CMAKE_DEPENDS_IN_PROJECT_ONLY OFF)

# The set of languages for which implicit dependencies are needed:
set(CMAKE_DEPENDS_LANGUAGES
  )

# The set of dependency files which are needed:
set(CMAKE_DEPENDS_DEPENDENCY_FILES
  "/work/main/server/cli_context.cpp" "server/CMakeFiles/fleetmap_cli.dir/cli_context.cpp.o" "gcc" "server/CMakeFiles/fleetmap_cli.dir/cli_context.cpp.o.d"
  "/work/main/server/map_commands.cpp" "server/CMakeFiles/fleetmap_cli.dir/map_commands.cpp.o" "gcc" "server/CMakeFiles/fleetmap_cli.dir/map_commands.cpp.o.d"
  "/work/main/server/robot_commands.cpp" "server/CMakeFiles/fleetmap_cli.dir/robot_commands.cpp.o" "gcc" "server/CMakeFiles/fleetmap_cli.dir/robot_commands.cpp.o.d"
  )

# Targets to which this target links.
set(CMAKE_TARGET_LINKED_INFO_FILES
  "/work/main/build-helper-r/protocol/CMakeFiles/fleetmap_protocol.dir/DependInfo.cmake"
  "/work/main/build-helper-r/common/CMakeFiles/fleetmap_common.dir/DependInfo.cmake"
  )

# Fortran module output directory.
set(CMAKE_Fortran_TARGET_MODULE_DIR "")
