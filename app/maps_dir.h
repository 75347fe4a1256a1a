#pragma once
// Where the real maps are read (the AMRL vector maps and navigation graphs, the GIS
// datasets): they are never copied into the repository, only read where they are kept.
#include <string>
#include <string_view>

namespace fleetmap {

// $FLEETMAP_MAPS_DIR when set and not empty, else the folder given at build time (CMake
// cache variable FLEETMAP_MAPS_DIR, default ../shared/maps beside the checkout), with
// "." and ".." taken out.
std::string maps_dir();

// maps_dir() + "/" + file, e.g. real_map_path("GDC1.vectormap.txt").
std::string real_map_path(std::string_view file);

}  // namespace fleetmap
