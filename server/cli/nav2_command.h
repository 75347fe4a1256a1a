#pragma once
// fleetmap map nav2: what a robot needs to run Nav2 on a stored map (seed 004's per-robot
// maps, docs/semantic-layer.md), for its laser height:
//
//   PREFIX.pgm + PREFIX.yaml                  map_server's occupancy grid: the slice at hL
//                                             with the objects seen at hL (docs/map-format.md)
//   PREFIX_keepout.pgm + PREFIX_keepout.yaml  the KeepoutFilter's mask: the map's avoided
//                                             areas, black (occupied = keep out), on the
//                                             same cells as the grid
//
//   fleetmap map nav2 NAME (--robot R | --laser-height H) -o PREFIX [--resolution R] [--image pgm|png]
//
// --image png writes PREFIX.png and PREFIX_keepout.png instead (the same pixels, GDAL's
// PNG driver; map_server loads PNG through the YAML's image: key), each with a world
// file (.pgw) that places it in the map frame for GIS tools (common/gis/grid_png.h).
//
// --robot reads the robot's profile (robots.laser_height; NULL: kDefaultLaserHeight, the
// laser height of the seed's robot class; the server sends such a robot the unsliced map).
#include <CLI/CLI.hpp>

#include "app/cli_context.h"

namespace fleetmap {

inline constexpr double kDefaultLaserHeight = 0.3;

// Adds `nav2` to the existing `map` subcommand of app.
void add_nav2_command(CLI::App& app, CliContext& ctx);

}  // namespace fleetmap
