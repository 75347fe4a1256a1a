file(REMOVE_RECURSE
  "../bin/fleetmap"
  "../bin/fleetmap.pdb"
  "CMakeFiles/fleetmap.dir/fleetmap_main.cpp.o"
  "CMakeFiles/fleetmap.dir/fleetmap_main.cpp.o.d"
)

# Per-language clean rules from dependency scanning.
foreach(lang CXX)
  include(CMakeFiles/fleetmap.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
