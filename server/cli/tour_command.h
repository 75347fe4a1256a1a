#pragma once
// Topological maps from guided tours (seed 003 §III, docs/topology-tour.md):
//   topo tour build MAP --robot R [--tour NAME] [--merge M] [--replace] [--dry-run]
//       the robot's recorded TourEvent ops (tour_events) -> a graph on the stored map's
//       segments (common/planning/tour_builder.h) -> the map's topology tables, as
//       'topo import' stores a file; --dry-run prints the graph as navigation JSON.
//   topo tour list --robot R      the robot's tours and how many events each has
#include <CLI/CLI.hpp>

#include "app/cli_context.h"

namespace fleetmap {

void add_topo_tour_commands(CLI::App& topo, CliContext& ctx);

}  // namespace fleetmap
