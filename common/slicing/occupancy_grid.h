#pragma once
// Occupancy grids for Nav2 (seed 004, per-robot maps): a raster of a segment map (usually a
// slice, common/slicing/map_slice.h) and, later, of filled polygons (environment objects and
// keep-out zones, common/scene/scene.h), written as Nav2 map_server's PGM + YAML pair.
//
// Cells are half-open squares (common/geometry/grid_frame.h): cell (col, row) covers
// [x0 + col r, x0 + (col+1) r) x [y0 + row r, y0 + (row+1) r), with (x0, y0) = origin,
// the grid's lower-left corner, so every point of the plane is in exactly one cell. A segment occupies every cell that
// holds a point of it, plus, where it crosses a grid corner diagonally, the two other
// cells around that corner (supercover): its cells are 4-connected, so nothing can
// slip between two diagonal cells. Ties are decided on the grid coordinates
// (x - x0) / r as doubles, exactly, so a wall on a grid line is one cell thick.
#include <cstdint>
#include <string>
#include <vector>

#include "common/geometry/geometry.h"
#include "common/geometry/grid_frame.h"
#include "common/map/map.h"
#include "common/geometry/polygon.h"

namespace fleetmap {

// Refused above this many cells (200 M: 200 MB of cells, plus as much again in a PGM).
inline constexpr double kMaxGridCells = 200e6;

struct OccupancyGrid {
  // nav_msgs/OccupancyGrid values (unknown is -1 there, 255 as a byte).
  static constexpr uint8_t kFree = 0, kOccupied = 100, kUnknown = 255;

  double resolution = 0.05;  // metres per cell
  Point origin;              // lower-left corner of cell (0, 0), map frame
  int width = 0, height = 0;
  std::vector<uint8_t> cells;  // row-major, row 0 at the bottom (min y), as nav_msgs

  GridFrame frame() const { return {origin, resolution, width, height}; }
  uint8_t at(int col, int row) const { return cells[frame().index(col, row)]; }
  // Cells outside the grid are ignored.
  void set(int64_t col, int64_t row, uint8_t value) {
    const GridFrame f = frame();
    if (f.inside(col, row)) cells[f.index(col, row)] = value;
  }
};

// A grid whose lower-left corner is (r.xmin, r.ymin) and that holds every point of r:
// floor(extent / resolution) + 1 cells per axis. Throws std::invalid_argument for a
// resolution that is not finite and > 0, or a grid over kMaxGridCells.
OccupancyGrid make_grid(const Rect& r, double resolution, uint8_t fill = OccupancyGrid::kFree);

// The map's border; when the border is empty, the segments' bounds grown by margin.
// Throws std::invalid_argument when there is neither.
Rect grid_bounds(const Map& map, double margin = 1.0);

void draw_segment(OccupancyGrid& grid, Point a, Point b, uint8_t value = OccupancyGrid::kOccupied);

// Cells whose centre is inside the ring (boundary included), plus every cell its
// outline passes through.
void fill_polygon(OccupancyGrid& grid, const Polygon& ring, uint8_t value = OccupancyGrid::kOccupied);

// Every segment of the map, except the stairs' h = 0 closing segments (a static grid shows
// stairs as seen from below, see map_slice.h). Meant for a slice.
OccupancyGrid rasterize_map(const Map& map, double resolution);

// Binary PGM (P5, maxval 255), row 0 of the image at the top (max y), as map_server
// reads it: occupied 0 (black), free 254, unknown 205, as Nav2's map_saver writes them.
std::string write_pgm(const OccupancyGrid& grid);
// The PGM's pixels alone, line by line from the top (for other image formats).
std::string pgm_raster(const OccupancyGrid& grid);

// map_server's YAML for that image: mode trinary, the image's resolution and origin.
// free_thresh is 0.196, not the 0.25 of Nav2's map_saver before Nav2 PR #5278: with 0.25
// the unknown grey 205 ((255 - 205) / 255 = 0.196 < 0.25) would load as free.
std::string write_nav2_yaml(const OccupancyGrid& grid, const std::string& image_file_name);

}  // namespace fleetmap
