#pragma once
// Operator commands on topological graphs (SPEC 7, seed 003):
//   topo check FILE                                    validate a navigation JSON, no database
//   topo import MAP FILE [--replace]                   store the graph of a stored map
//   topo route MAP FROM TO [--no-stairs] [--radius R]  shortest route; FROM/TO: node id or X,Y
//   topo export MAP [--format json|geojson] [-o FILE]
//   topo delete MAP
//   topo tour build|list ...                           graphs from guided tours (tour_command.h)
// Exit codes (exit_codes.h): 2 malformed file or argument, 3 no route, 4 unknown map,
// graph or node, or a graph exists (import without --replace).
#include <CLI/CLI.hpp>

#include "app/cli_context.h"

namespace fleetmap {

// Adds the "topo" subcommand (with its subcommands) to app.
void add_topo_commands(CLI::App& app, CliContext& ctx);

}  // namespace fleetmap
