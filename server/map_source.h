#pragma once
// Where an operator command gets a map from: a stored map by name, or a map file
// (seed format; AMRL when the name ends with .vectormap.txt) without any database.
#include <string>

#include "common/map.h"
#include "server/cli_context.h"

namespace fleetmap {

bool is_amrl_file(const std::string& file);

// file empty: the stored map `name`; otherwise the file. Throws MapNotFound,
// MapFormatError.
Map load_map_source(const std::string& name, const std::string& file, CliContext& ctx);

}  // namespace fleetmap
