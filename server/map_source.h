#pragma once
// Where an operator command reads a map from (a stored map by name, or a map file: seed
// format, AMRL when the name ends with .vectormap.txt, without any database) and where
// it writes its output.
#include <string>

#include "common/map.h"
#include "server/cli_context.h"

namespace fleetmap {

bool is_amrl_file(const std::string& file);

// file empty: the stored map `name`; otherwise the file. Throws MapNotFound,
// MapFormatError.
Map load_map_source(const std::string& name, const std::string& file, CliContext& ctx);

// text to file, or to standard output when file is empty or "-"; throws on a write error.
void write_output(const std::string& text, const std::string& file);

}  // namespace fleetmap
