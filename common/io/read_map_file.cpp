#include "common/io/read_map_file.h"

#include "common/io/seed_format.h"

namespace fleetmap {

MapFileFormat map_file_format(std::string_view path) {
  return path.ends_with(kAmrlSuffix) ? MapFileFormat::Amrl : MapFileFormat::Seed;
}

Map read_map_file(const std::string& path, const AmrlOptions& amrl, AmrlReport* report) {
  if (map_file_format(path) == MapFileFormat::Amrl) return read_amrl_file(path, amrl, report);
  return read_seed_file(path);
}

}  // namespace fleetmap
