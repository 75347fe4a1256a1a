#include "app/maps_dir.h"

#include <cstdlib>
#include <filesystem>

#ifndef FLEETMAP_DEFAULT_MAPS_DIR
#error "FLEETMAP_DEFAULT_MAPS_DIR must name the folder of the real maps (app/CMakeLists.txt)"
#endif

namespace fleetmap {

std::string maps_dir() {
  const char* env = std::getenv("FLEETMAP_MAPS_DIR");
  if (env != nullptr && *env != '\0') return env;
  // The default is <checkout>/../shared/maps: printed in --help, so without the "..".
  return std::filesystem::path(FLEETMAP_DEFAULT_MAPS_DIR).lexically_normal().string();
}

std::string real_map_path(std::string_view file) { return maps_dir() + "/" + std::string(file); }

}  // namespace fleetmap
