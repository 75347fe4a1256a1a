
# Consider dependencies only in project.
set(CMAKE_DEPENDS_IN_PROJECT_ONLY OFF)

# The set of languages for which implicit dependencies are needed:
set(CMAKE_DEPENDS_LANGUAGES
  )

# The set of dependency files which are needed:
set(CMAKE_DEPENDS_DEPENDENCY_FILES
  "/work/main/tests/common/amrl_import_test.cpp" "tests/CMakeFiles/common_tests.dir/common/amrl_import_test.cpp.o" "gcc" "tests/CMakeFiles/common_tests.dir/common/amrl_import_test.cpp.o.d"
  "/work/main/tests/common/bounding_circle_test.cpp" "tests/CMakeFiles/common_tests.dir/common/bounding_circle_test.cpp.o" "gcc" "tests/CMakeFiles/common_tests.dir/common/bounding_circle_test.cpp.o.d"
  "/work/main/tests/common/example_map_test.cpp" "tests/CMakeFiles/common_tests.dir/common/example_map_test.cpp.o" "gcc" "tests/CMakeFiles/common_tests.dir/common/example_map_test.cpp.o.d"
  "/work/main/tests/common/geometry_test.cpp" "tests/CMakeFiles/common_tests.dir/common/geometry_test.cpp.o" "gcc" "tests/CMakeFiles/common_tests.dir/common/geometry_test.cpp.o.d"
  "/work/main/tests/common/map_geojson_test.cpp" "tests/CMakeFiles/common_tests.dir/common/map_geojson_test.cpp.o" "gcc" "tests/CMakeFiles/common_tests.dir/common/map_geojson_test.cpp.o.d"
  "/work/main/tests/common/map_svg_test.cpp" "tests/CMakeFiles/common_tests.dir/common/map_svg_test.cpp.o" "gcc" "tests/CMakeFiles/common_tests.dir/common/map_svg_test.cpp.o.d"
  "/work/main/tests/common/map_window_test.cpp" "tests/CMakeFiles/common_tests.dir/common/map_window_test.cpp.o" "gcc" "tests/CMakeFiles/common_tests.dir/common/map_window_test.cpp.o.d"
  "/work/main/tests/common/ramp_stairs_test.cpp" "tests/CMakeFiles/common_tests.dir/common/ramp_stairs_test.cpp.o" "gcc" "tests/CMakeFiles/common_tests.dir/common/ramp_stairs_test.cpp.o.d"
  "/work/main/tests/common/ray_caster_equivalence_test.cpp" "tests/CMakeFiles/common_tests.dir/common/ray_caster_equivalence_test.cpp.o" "gcc" "tests/CMakeFiles/common_tests.dir/common/ray_caster_equivalence_test.cpp.o.d"
  "/work/main/tests/common/ray_caster_rules_test.cpp" "tests/CMakeFiles/common_tests.dir/common/ray_caster_rules_test.cpp.o" "gcc" "tests/CMakeFiles/common_tests.dir/common/ray_caster_rules_test.cpp.o.d"
  "/work/main/tests/common/ray_caster_segment_test.cpp" "tests/CMakeFiles/common_tests.dir/common/ray_caster_segment_test.cpp.o" "gcc" "tests/CMakeFiles/common_tests.dir/common/ray_caster_segment_test.cpp.o.d"
  "/work/main/tests/common/seed_format_malformed_test.cpp" "tests/CMakeFiles/common_tests.dir/common/seed_format_malformed_test.cpp.o" "gcc" "tests/CMakeFiles/common_tests.dir/common/seed_format_malformed_test.cpp.o.d"
  "/work/main/tests/common/seed_format_roundtrip_test.cpp" "tests/CMakeFiles/common_tests.dir/common/seed_format_roundtrip_test.cpp.o" "gcc" "tests/CMakeFiles/common_tests.dir/common/seed_format_roundtrip_test.cpp.o.d"
  )

# Targets to which this target links.
set(CMAKE_TARGET_LINKED_INFO_FILES
  "/work/main/build-helper-r/common/CMakeFiles/fleetmap_common.dir/DependInfo.cmake"
  )

# Fortran module output directory.
set(CMAKE_Fortran_TARGET_MODULE_DIR "")
