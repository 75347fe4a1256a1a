#pragma once
// Where the cells of a uniform grid of squares lie in the map frame: the one statement
// of the arithmetic that every grid over a map shares (the ray casters' segment and
// candidate grids, the clearance checker, the A* grid, the occupancy grids, the
// localization's distance field). What a cell holds is each grid's own business.
//
// Cells are half-open squares: cell (ix, iy) covers [x0 + ix c, x0 + (ix+1) c) x
// [y0 + iy c, y0 + (iy+1) c), with (x0, y0) = origin, the lower-left corner of cell
// (0, 0), and c = cell. Every point of the plane is in exactly one cell (column and row
// may lie outside [0, width) x [0, height)). A point's cell is decided on its grid
// coordinates (x - x0) / c, a division, not a multiplication by 1 / c: a point on a grid
// line is in the cell above and right of it whenever the line's own coordinate is
// exactly k c from the origin.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>

#include "common/geometry/geometry.h"

namespace fleetmap {

// Columns x0..x1 and rows y0..y1, both ends included; empty when x0 > x1 or y0 > y1.
struct CellRange {
  int x0 = 0, x1 = -1, y0 = 0, y1 = -1;
  bool empty() const { return x0 > x1 || y0 > y1; }
  friend bool operator==(const CellRange&, const CellRange&) = default;
};

struct GridFrame {
  Point origin;     // lower-left corner of cell (0, 0), map frame
  double cell = 1;  // side of a cell, metres, > 0
  int width = 0;    // columns, along x
  int height = 0;   // rows, along y

  size_t cells() const { return static_cast<size_t>(width) * static_cast<size_t>(height); }
  // The rectangle the cells cover.
  Rect rect() const { return {origin.x, origin.y, origin.x + width * cell, origin.y + height * cell}; }

  // Grid coordinates: cell (i, j) is [i, i+1) x [j, j+1) there.
  double grid_x(double x) const { return (x - origin.x) / cell; }
  double grid_y(double y) const { return (y - origin.y) / cell; }
  Point to_grid(Point p) const { return {grid_x(p.x), grid_y(p.y)}; }

  // The column and row holding x and y, not bounded by the grid. Here and below,
  // coordinates are finite and within 2^31 cells of the origin (map_validation.h's
  // kMaxCoordinate keeps them there).
  int64_t col(double x) const { return static_cast<int64_t>(std::floor(grid_x(x))); }
  int64_t row(double y) const { return static_cast<int64_t>(std::floor(grid_y(y))); }
  // The nearest column and row of the grid (the grid must not be empty).
  int clamp_col(double x) const { return clamp_to(grid_x(x), width); }
  int clamp_row(double y) const { return clamp_to(grid_y(y), height); }

  bool inside(int64_t ix, int64_t iy) const { return ix >= 0 && iy >= 0 && ix < width && iy < height; }
  // Row-major, row 0 at the bottom (min y).
  size_t index(int64_t ix, int64_t iy) const { return static_cast<size_t>(iy) * width + static_cast<size_t>(ix); }
  // The index of p's cell; nullopt when p is outside the grid (or not a number).
  std::optional<size_t> index_of(Point p) const {
    const double fx = std::floor(grid_x(p.x)), fy = std::floor(grid_y(p.y));
    if (!(fx >= 0 && fy >= 0 && fx < width && fy < height)) return std::nullopt;
    return index(static_cast<int64_t>(fx), static_cast<int64_t>(fy));
  }

  Point centre(int64_t ix, int64_t iy) const {
    return {origin.x + (static_cast<double>(ix) + 0.5) * cell, origin.y + (static_cast<double>(iy) + 0.5) * cell};
  }
  // The closed square of the cell; neighbours share their edges bit for bit.
  Rect cell_rect(int64_t ix, int64_t iy) const {
    const double x = static_cast<double>(ix), y = static_cast<double>(iy);
    return {origin.x + x * cell, origin.y + y * cell, origin.x + (x + 1) * cell, origin.y + (y + 1) * cell};
  }

  // The grid's cells that hold a point of the closed rectangle r (empty when r misses
  // the grid or is inverted).
  CellRange cells_covering(const Rect& r) const {
    if (!(r.xmin <= r.xmax && r.ymin <= r.ymax)) return {};
    return {bound_below(grid_x(r.xmin)), bound_above(grid_x(r.xmax), width), bound_below(grid_y(r.ymin)),
            bound_above(grid_y(r.ymax), height)};
  }

  // Calls f(ix, iy) for every cell of the grid that segment ab grown by `grow` (>= 0)
  // may meet, column by column, bottom to top; stops early when f returns false. In
  // each column the rows run between the segment's lowest and highest point over the
  // column's x range grown by `grow`, themselves grown by `grow`: a superset of the
  // cells within `grow` of ab, as tight as one interval a column can be. Returns false
  // when f stopped the walk.
  template <class F>
  bool for_cells_near_segment(Point a, Point b, double grow, F&& f) const {
    const Point e = b - a;
    const int c0 = bound_below(grid_x(std::min(a.x, b.x) - grow)), c1 = bound_above(grid_x(std::max(a.x, b.x) + grow), width);
    for (int ix = c0; ix <= c1; ++ix) {
      double u0 = 0, u1 = 1;  // the part of ab over the column, as fractions of ab
      if (e.x != 0) {
        const double x0 = origin.x + ix * cell - grow, x1 = x0 + cell + 2 * grow;
        u0 = std::clamp((x0 - a.x) / e.x, 0.0, 1.0);
        u1 = std::clamp((x1 - a.x) / e.x, 0.0, 1.0);
      }
      const double y0 = a.y + u0 * e.y, y1 = a.y + u1 * e.y;
      const int r0 = bound_below(grid_y(std::min(y0, y1) - grow)), r1 = bound_above(grid_y(std::max(y0, y1) + grow), height);
      for (int iy = r0; iy <= r1; ++iy)
        if (!f(ix, iy)) return false;
    }
    return true;
  }

 private:
  static int clamp_to(double g, int n) {
    return static_cast<int>(std::clamp(std::floor(g), 0.0, static_cast<double>(n - 1)));
  }
  // floor(g) bounded below by 0 (and above by INT_MAX, which no grid reaches).
  static int bound_below(double g) { return static_cast<int>(std::clamp(std::floor(g), 0.0, 2147483647.0)); }
  // floor(g) bounded above by n - 1 (and below by -1: an empty range).
  static int bound_above(double g, int n) {
    return static_cast<int>(std::clamp(std::floor(g), -1.0, static_cast<double>(n - 1)));
  }
};

}  // namespace fleetmap
