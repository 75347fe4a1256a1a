file(REMOVE_RECURSE
  "../bin/integration_tests"
  "../bin/integration_tests.pdb"
  "CMakeFiles/integration_tests.dir/integration/accounts_test.cpp.o"
  "CMakeFiles/integration_tests.dir/integration/accounts_test.cpp.o.d"
  "CMakeFiles/integration_tests.dir/integration/map_import_test.cpp.o"
  "CMakeFiles/integration_tests.dir/integration/map_import_test.cpp.o.d"
  "CMakeFiles/integration_tests.dir/integration/map_window_test.cpp.o"
  "CMakeFiles/integration_tests.dir/integration/map_window_test.cpp.o.d"
  "CMakeFiles/integration_tests.dir/integration/protocol_robot_test.cpp.o"
  "CMakeFiles/integration_tests.dir/integration/protocol_robot_test.cpp.o.d"
  "CMakeFiles/integration_tests.dir/integration/server_fixture.cpp.o"
  "CMakeFiles/integration_tests.dir/integration/server_fixture.cpp.o.d"
  "CMakeFiles/integration_tests.dir/integration/test_db.cpp.o"
  "CMakeFiles/integration_tests.dir/integration/test_db.cpp.o.d"
  "integration_tests[1]_tests.cmake"
)

# Per-language clean rules from dependency scanning.
foreach(lang CXX)
  include(CMakeFiles/integration_tests.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
