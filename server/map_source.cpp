#include "server/map_source.h"

#include <fstream>
#include <iostream>
#include <stdexcept>

#include "common/amrl_import.h"
#include "common/seed_format.h"
#include "protocol/map_store.h"

namespace fleetmap {

bool is_amrl_file(const std::string& file) {
  const std::string suffix = ".vectormap.txt";
  return file.size() >= suffix.size() && file.compare(file.size() - suffix.size(), suffix.size(), suffix) == 0;
}

Map load_map_source(const std::string& name, const std::string& file, CliContext& ctx) {
  if (file.empty()) return MapStore(ctx.connection()).load(name);
  return is_amrl_file(file) ? read_amrl_file(file, AmrlOptions{}) : read_seed_file(file);
}

void write_output(const std::string& text, const std::string& file) {
  if (file.empty() || file == "-") {
    std::cout << text;
    return;
  }
  std::ofstream out(file, std::ios::binary);
  out << text;
  if (!out) throw std::runtime_error("cannot write '" + file + "'");
}

}  // namespace fleetmap
