#pragma once
// Operator commands on the GIS layers (docs/gis-layers.md): gis publish [MAP...], gis list.
#include <CLI/CLI.hpp>

#include "app/cli_context.h"

namespace fleetmap {

// Adds the "gis" subcommand (with its subcommands) to app.
void add_gis_commands(CLI::App& app, CliContext& ctx);

}  // namespace fleetmap
