file(REMOVE_RECURSE
  "CMakeFiles/fleetmap_common.dir/amrl_import.cpp.o"
  "CMakeFiles/fleetmap_common.dir/amrl_import.cpp.o.d"
  "CMakeFiles/fleetmap_common.dir/bounding_circle.cpp.o"
  "CMakeFiles/fleetmap_common.dir/bounding_circle.cpp.o.d"
  "CMakeFiles/fleetmap_common.dir/geometry.cpp.o"
  "CMakeFiles/fleetmap_common.dir/geometry.cpp.o.d"
  "CMakeFiles/fleetmap_common.dir/map.cpp.o"
  "CMakeFiles/fleetmap_common.dir/map.cpp.o.d"
  "CMakeFiles/fleetmap_common.dir/map_validation.cpp.o"
  "CMakeFiles/fleetmap_common.dir/map_validation.cpp.o.d"
  "CMakeFiles/fleetmap_common.dir/map_window.cpp.o"
  "CMakeFiles/fleetmap_common.dir/map_window.cpp.o.d"
  "CMakeFiles/fleetmap_common.dir/ramp.cpp.o"
  "CMakeFiles/fleetmap_common.dir/ramp.cpp.o.d"
  "CMakeFiles/fleetmap_common.dir/seed_format.cpp.o"
  "CMakeFiles/fleetmap_common.dir/seed_format.cpp.o.d"
  "libfleetmap_common.a"
  "libfleetmap_common.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang CXX)
  include(CMakeFiles/fleetmap_common.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
