
# Consider dependencies only in project.
set(CMAKE_DEPENDS_IN_PROJECT_ONLY OFF)

# The set of languages for which implicit dependencies are needed:
set(CMAKE_DEPENDS_LANGUAGES
  )

# The set of dependency files which are needed:
set(CMAKE_DEPENDS_DEPENDENCY_FILES
  "/work/main/tests/integration/accounts_test.cpp" "tests/CMakeFiles/integration_tests.dir/integration/accounts_test.cpp.o" "gcc" "tests/CMakeFiles/integration_tests.dir/integration/accounts_test.cpp.o.d"
  "/work/main/tests/integration/map_import_test.cpp" "tests/CMakeFiles/integration_tests.dir/integration/map_import_test.cpp.o" "gcc" "tests/CMakeFiles/integration_tests.dir/integration/map_import_test.cpp.o.d"
  "/work/main/tests/integration/map_window_test.cpp" "tests/CMakeFiles/integration_tests.dir/integration/map_window_test.cpp.o" "gcc" "tests/CMakeFiles/integration_tests.dir/integration/map_window_test.cpp.o.d"
  "/work/main/tests/integration/protocol_robot_test.cpp" "tests/CMakeFiles/integration_tests.dir/integration/protocol_robot_test.cpp.o" "gcc" "tests/CMakeFiles/integration_tests.dir/integration/protocol_robot_test.cpp.o.d"
  "/work/main/tests/integration/server_fixture.cpp" "tests/CMakeFiles/integration_tests.dir/integration/server_fixture.cpp.o" "gcc" "tests/CMakeFiles/integration_tests.dir/integration/server_fixture.cpp.o.d"
  "/work/main/tests/integration/test_db.cpp" "tests/CMakeFiles/integration_tests.dir/integration/test_db.cpp.o" "gcc" "tests/CMakeFiles/integration_tests.dir/integration/test_db.cpp.o.d"
  )

# Targets to which this target links.
set(CMAKE_TARGET_LINKED_INFO_FILES
  "/work/main/build-helper-r/protocol/CMakeFiles/fleetmap_protocol.dir/DependInfo.cmake"
  "/work/main/build-helper-r/common/CMakeFiles/fleetmap_common.dir/DependInfo.cmake"
  )

# Fortran module output directory.
set(CMAKE_Fortran_TARGET_MODULE_DIR "")
