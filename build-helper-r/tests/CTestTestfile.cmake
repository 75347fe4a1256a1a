# CMake generated Testfile for 
# Source directory: /work/main/tests
# Build directory: /work/main/build-helper-r/tests
# 
# This file includes the relevant testing commands required for 
# testing this directory and lists subdirectories to be tested as well.
include("/work/main/build-helper-r/tests/common_tests[1]_include.cmake")
include("/work/main/build-helper-r/tests/integration_tests[1]_include.cmake")
add_test([=[db_start]=] "/usr/bin/cmake" "-E" "env" "FLEETMAP_HOME=/work/main/build-helper-r/testdb" "FLEETMAP_PORT=33307" "bash" "/work/main/scripts/db.sh" "start")
set_tests_properties([=[db_start]=] PROPERTIES  FIXTURES_SETUP "db" _BACKTRACE_TRIPLES "/work/main/tests/CMakeLists.txt;25;add_test;/work/main/tests/CMakeLists.txt;0;")
add_test([=[db_stop]=] "/usr/bin/cmake" "-E" "env" "FLEETMAP_HOME=/work/main/build-helper-r/testdb" "FLEETMAP_PORT=33307" "bash" "/work/main/scripts/db.sh" "stop")
set_tests_properties([=[db_stop]=] PROPERTIES  FIXTURES_CLEANUP "db" _BACKTRACE_TRIPLES "/work/main/tests/CMakeLists.txt;26;add_test;/work/main/tests/CMakeLists.txt;0;")
