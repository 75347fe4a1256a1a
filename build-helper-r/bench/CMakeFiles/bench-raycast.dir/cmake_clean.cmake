file(REMOVE_RECURSE
  "../bin/bench-raycast"
  "../bin/bench-raycast.pdb"
  "CMakeFiles/bench-raycast.dir/bench_raycast.cpp.o"
  "CMakeFiles/bench-raycast.dir/bench_raycast.cpp.o.d"
)

# Per-language clean rules from dependency scanning.
foreach(lang CXX)
  include(CMakeFiles/bench-raycast.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
