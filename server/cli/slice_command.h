#pragma once
// fleetmap map slice: the per-robot map of seed 004, what a laser at height H sees of a
// stored map or a map file (common/slicing/map_slice.h), as a segment map in the seed format or
// as a Nav2 occupancy grid (common/slicing/occupancy_grid.h: OUTPUT.pgm + OUTPUT.yaml).
//
//   fleetmap map slice NAME --height H [--format seed|pgm] [-o OUTPUT] [--resolution R]
//   fleetmap map slice --file F --height H ...     (no database)
#include <CLI/CLI.hpp>

#include "app/cli_context.h"

namespace fleetmap {

// Adds `slice` to the existing `map` subcommand of app.
void add_slice_command(CLI::App& app, CliContext& ctx);

}  // namespace fleetmap
