#pragma once
// map georef: read, set and fit a map's georeference (docs/georeference.md).
//   map georef NAME                                 print it (base CRS, similarity, corners, control points)
//   map georef NAME LAT LON [--heading H]           the map origin's fix and the x axis's heading
//   map georef NAME --control x,y,lat,lon ...       a least-squares fit to >= 2 control points
//   map georef NAME --crs CRS [--offset TX,TY] [--rotation RAD]   the frame in a projected CRS
//   map georef NAME --clear                         remove it and its control points
#include <CLI/CLI.hpp>

#include "app/cli_context.h"

namespace fleetmap {

void add_map_georef(CLI::App& map, CliContext& ctx);

}  // namespace fleetmap
