file(REMOVE_RECURSE
  "../bin/bench-map"
  "../bin/bench-map.pdb"
  "CMakeFiles/bench-map.dir/bench_map.cpp.o"
  "CMakeFiles/bench-map.dir/bench_map.cpp.o.d"
)

# Per-language clean rules from dependency scanning.
foreach(lang CXX)
  include(CMakeFiles/bench-map.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
