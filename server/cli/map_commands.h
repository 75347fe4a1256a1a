#pragma once
// Operator commands on maps: map check|import|export|list|delete|georef, and window.
#include <CLI/CLI.hpp>

#include "app/cli_context.h"

namespace fleetmap {

// Adds the "map" subcommand (with its subcommands) and "window" to app.
void add_map_commands(CLI::App& app, CliContext& ctx);

}  // namespace fleetmap
