#pragma once
// Operator commands on robots and tasks: robot add|list|set|remove, robots, goal,
// pose-ini, abort, tasks, trajectory.
#include <CLI/CLI.hpp>

#include "app/cli_context.h"

namespace fleetmap {

void add_robot_commands(CLI::App& app, CliContext& ctx);

}  // namespace fleetmap
