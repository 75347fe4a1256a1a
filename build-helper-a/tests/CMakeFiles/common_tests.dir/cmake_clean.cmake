file(REMOVE_RECURSE
  "../bin/common_tests"
  "../bin/common_tests.pdb"
  "CMakeFiles/common_tests.dir/common/example_map_test.cpp.o"
  "CMakeFiles/common_tests.dir/common/example_map_test.cpp.o.d"
  "common_tests[1]_tests.cmake"
)

# Per-language clean rules from dependency scanning.
foreach(lang CXX)
  include(CMakeFiles/common_tests.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
