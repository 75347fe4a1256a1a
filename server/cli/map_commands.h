#pragma once
// Operator commands on maps: map import|export|list|check|delete, and window.
#include <CLI/CLI.hpp>

#include "app/cli_context.h"

namespace fleetmap {

// Adds the subcommands to app; each sets *exit_code when it runs.
void add_map_commands(CLI::App& app, CliContext& ctx, int* exit_code);

}  // namespace fleetmap
