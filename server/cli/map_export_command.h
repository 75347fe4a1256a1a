#pragma once
// fleetmap map export NAME: a stored map for other programs and GIS tools.
//
//   --format seed     the seed text format (the interchange format; map frame)
//   --format geojson  RFC 7946: WGS 84 for a georeferenced map, --crs map for the map frame
//   --format svg      a drawing, optionally with the robots' trajectories
//   --format gpkg|fgb|DRIVER   GIS layers through OGR (common/gis/ogr_export.h): the map,
//                     its objects, avoided areas and bounds, its topological graph, and
//                     with --trajectories the robots' trajectories; map frame with its CRS
//                     by default, --crs base|wgs84 to transform
#include <CLI/CLI.hpp>

#include "app/cli_context.h"

namespace fleetmap {

// Adds `export` to the `map` subcommand.
void add_map_export(CLI::App& map, CliContext& ctx);

}  // namespace fleetmap
