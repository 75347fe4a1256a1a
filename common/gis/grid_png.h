#pragma once
// An occupancy grid as a PNG for Nav2 and GIS tools: the PGM's pixels (map_server reads
// PNG through the YAML's image: key as it reads PGM), 8-bit grey, written by GDAL's PNG
// driver; a world file beside it (PATH without its extension + ".pgw": pixel size and
// the centre of the upper-left pixel, in the map frame) so GIS tools overlay the grid;
// with a CRS, its WKT in PATH.aux.xml (GDAL's PAM), which QGIS and GDAL read.
#include <cstdint>
#include <string>

#include "common/slicing/occupancy_grid.h"

namespace fleetmap {

// The world file of the grid (six lines: A D B E C F, ESRI's order).
std::string grid_world_file(const OccupancyGrid& grid);

// Writes PATH (PNG) and its world file; crs_wkt empty: no CRS. Throws IoError. Returns
// the PNG's size in bytes.
uintmax_t write_grid_png(const OccupancyGrid& grid, const std::string& path, const std::string& crs_wkt = "");

// PATH with its extension replaced by ".pgw" (or ".pgw" appended when it has none).
std::string world_file_path(const std::string& png_path);

}  // namespace fleetmap
