file(REMOVE_RECURSE
  "../bin/fleetmap-robot"
  "../bin/fleetmap-robot.pdb"
  "CMakeFiles/fleetmap-robot.dir/robot_main.cpp.o"
  "CMakeFiles/fleetmap-robot.dir/robot_main.cpp.o.d"
)

# Per-language clean rules from dependency scanning.
foreach(lang CXX)
  include(CMakeFiles/fleetmap-robot.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
