
# Consider dependencies only in project.
set(CMAKE_DEPENDS_IN_PROJECT_ONLY OFF)

# The set of languages for which implicit dependencies are needed:
set(CMAKE_DEPENDS_LANGUAGES
  )

# The set of dependency files which are needed:
set(CMAKE_DEPENDS_DEPENDENCY_FILES
  "/work/main/common/amrl_import.cpp" "common/CMakeFiles/fleetmap_common.dir/amrl_import.cpp.o" "gcc" "common/CMakeFiles/fleetmap_common.dir/amrl_import.cpp.o.d"
  "/work/main/common/bounding_circle.cpp" "common/CMakeFiles/fleetmap_common.dir/bounding_circle.cpp.o" "gcc" "common/CMakeFiles/fleetmap_common.dir/bounding_circle.cpp.o.d"
  "/work/main/common/geometry.cpp" "common/CMakeFiles/fleetmap_common.dir/geometry.cpp.o" "gcc" "common/CMakeFiles/fleetmap_common.dir/geometry.cpp.o.d"
  "/work/main/common/grid_ray_caster.cpp" "common/CMakeFiles/fleetmap_common.dir/grid_ray_caster.cpp.o" "gcc" "common/CMakeFiles/fleetmap_common.dir/grid_ray_caster.cpp.o.d"
  "/work/main/common/map.cpp" "common/CMakeFiles/fleetmap_common.dir/map.cpp.o" "gcc" "common/CMakeFiles/fleetmap_common.dir/map.cpp.o.d"
  "/work/main/common/map_geojson.cpp" "common/CMakeFiles/fleetmap_common.dir/map_geojson.cpp.o" "gcc" "common/CMakeFiles/fleetmap_common.dir/map_geojson.cpp.o.d"
  "/work/main/common/map_svg.cpp" "common/CMakeFiles/fleetmap_common.dir/map_svg.cpp.o" "gcc" "common/CMakeFiles/fleetmap_common.dir/map_svg.cpp.o.d"
  "/work/main/common/map_validation.cpp" "common/CMakeFiles/fleetmap_common.dir/map_validation.cpp.o" "gcc" "common/CMakeFiles/fleetmap_common.dir/map_validation.cpp.o.d"
  "/work/main/common/map_window.cpp" "common/CMakeFiles/fleetmap_common.dir/map_window.cpp.o" "gcc" "common/CMakeFiles/fleetmap_common.dir/map_window.cpp.o.d"
  "/work/main/common/ramp.cpp" "common/CMakeFiles/fleetmap_common.dir/ramp.cpp.o" "gcc" "common/CMakeFiles/fleetmap_common.dir/ramp.cpp.o.d"
  "/work/main/common/ray_caster.cpp" "common/CMakeFiles/fleetmap_common.dir/ray_caster.cpp.o" "gcc" "common/CMakeFiles/fleetmap_common.dir/ray_caster.cpp.o.d"
  "/work/main/common/ray_rules.cpp" "common/CMakeFiles/fleetmap_common.dir/ray_rules.cpp.o" "gcc" "common/CMakeFiles/fleetmap_common.dir/ray_rules.cpp.o.d"
  "/work/main/common/ray_segment.cpp" "common/CMakeFiles/fleetmap_common.dir/ray_segment.cpp.o" "gcc" "common/CMakeFiles/fleetmap_common.dir/ray_segment.cpp.o.d"
  "/work/main/common/seed_format.cpp" "common/CMakeFiles/fleetmap_common.dir/seed_format.cpp.o" "gcc" "common/CMakeFiles/fleetmap_common.dir/seed_format.cpp.o.d"
  "/work/main/common/seed_ray_caster.cpp" "common/CMakeFiles/fleetmap_common.dir/seed_ray_caster.cpp.o" "gcc" "common/CMakeFiles/fleetmap_common.dir/seed_ray_caster.cpp.o.d"
  "/work/main/common/segment_grid.cpp" "common/CMakeFiles/fleetmap_common.dir/segment_grid.cpp.o" "gcc" "common/CMakeFiles/fleetmap_common.dir/segment_grid.cpp.o.d"
  )

# Targets to which this target links.
set(CMAKE_TARGET_LINKED_INFO_FILES
  )

# Fortran module output directory.
set(CMAKE_Fortran_TARGET_MODULE_DIR "")
