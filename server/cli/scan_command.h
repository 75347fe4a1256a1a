#pragma once
// fleetmap scan: what a laser sees from a pose on a map (SPEC 6): one `angle range` line
// per beam. People use it to check a map; tests and benchmarks use it too.
#include <CLI/CLI.hpp>

#include "app/cli_context.h"

namespace fleetmap {

void add_scan_command(CLI::App& app, CliContext& ctx);

}  // namespace fleetmap
