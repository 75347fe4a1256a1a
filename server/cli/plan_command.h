#pragma once
// Operator command: plan a path on a stored map or a map file (SPEC 7).
//
//   fleetmap plan MAP X1 Y1 X2 Y2 [--radius R] [--body-height H] [--seed S] [--svg OUT] ...
//   fleetmap plan --file F [--objects F.geojson] X1 Y1 X2 Y2 ...   (seed format, or AMRL for
//                                               *.vectormap.txt; no database)
//
// The map's objects whose range starts below H block, and every avoided area
// (docs/semantic-layer.md, common/planning/planning_scene.h): a stored map's scene, or --objects with --file; --no-objects
// plans on the segments alone.
//
// Prints the smoothed path on standard output, one "x y" waypoint a line (millimetres),
// then "length L"; a summary goes to standard error. Exit codes (app/exit_codes.h):
//   0  a path was found
//   1  failure: the database, or a map file that cannot be read
//   2  malformed input: a map file, a coordinate, an option value
//   3  no path: the start or the goal is blocked (within R of an obstacle, on stairs
//      for a wheeled robot, or outside the border), or RRT-Connect found none within
//      its limits; standard error says which
//   4  no such stored map
//   64 wrong command line
#include <CLI/CLI.hpp>

#include "app/cli_context.h"

namespace fleetmap {

// Adds the "plan" subcommand to app.
void add_plan_command(CLI::App& app, CliContext& ctx);

}  // namespace fleetmap
