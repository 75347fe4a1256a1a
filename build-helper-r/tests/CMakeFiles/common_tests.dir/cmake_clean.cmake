file(REMOVE_RECURSE
  "../bin/common_tests"
  "../bin/common_tests.pdb"
  "CMakeFiles/common_tests.dir/common/amrl_import_test.cpp.o"
  "CMakeFiles/common_tests.dir/common/amrl_import_test.cpp.o.d"
  "CMakeFiles/common_tests.dir/common/bounding_circle_test.cpp.o"
  "CMakeFiles/common_tests.dir/common/bounding_circle_test.cpp.o.d"
  "CMakeFiles/common_tests.dir/common/example_map_test.cpp.o"
  "CMakeFiles/common_tests.dir/common/example_map_test.cpp.o.d"
  "CMakeFiles/common_tests.dir/common/geometry_test.cpp.o"
  "CMakeFiles/common_tests.dir/common/geometry_test.cpp.o.d"
  "CMakeFiles/common_tests.dir/common/map_geojson_test.cpp.o"
  "CMakeFiles/common_tests.dir/common/map_geojson_test.cpp.o.d"
  "CMakeFiles/common_tests.dir/common/map_svg_test.cpp.o"
  "CMakeFiles/common_tests.dir/common/map_svg_test.cpp.o.d"
  "CMakeFiles/common_tests.dir/common/map_window_test.cpp.o"
  "CMakeFiles/common_tests.dir/common/map_window_test.cpp.o.d"
  "CMakeFiles/common_tests.dir/common/ramp_stairs_test.cpp.o"
  "CMakeFiles/common_tests.dir/common/ramp_stairs_test.cpp.o.d"
  "CMakeFiles/common_tests.dir/common/ray_caster_equivalence_test.cpp.o"
  "CMakeFiles/common_tests.dir/common/ray_caster_equivalence_test.cpp.o.d"
  "CMakeFiles/common_tests.dir/common/ray_caster_rules_test.cpp.o"
  "CMakeFiles/common_tests.dir/common/ray_caster_rules_test.cpp.o.d"
  "CMakeFiles/common_tests.dir/common/ray_caster_segment_test.cpp.o"
  "CMakeFiles/common_tests.dir/common/ray_caster_segment_test.cpp.o.d"
  "CMakeFiles/common_tests.dir/common/seed_format_malformed_test.cpp.o"
  "CMakeFiles/common_tests.dir/common/seed_format_malformed_test.cpp.o.d"
  "CMakeFiles/common_tests.dir/common/seed_format_roundtrip_test.cpp.o"
  "CMakeFiles/common_tests.dir/common/seed_format_roundtrip_test.cpp.o.d"
  "common_tests[1]_tests.cmake"
)

# Per-language clean rules from dependency scanning.
foreach(lang CXX)
  include(CMakeFiles/common_tests.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
