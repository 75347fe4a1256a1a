#include "common/slicing/occupancy_grid.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "common/geometry/number_format.h"

namespace fleetmap {
namespace {

// Grid coordinates (GridFrame::to_grid): cell (i, j) is [i, i+1) x [j, j+1).
Point to_grid(const OccupancyGrid& g, Point p) { return g.frame().to_grid(p); }

// The cell of a grid coordinate.
int64_t cell_index(double u) { return static_cast<int64_t>(std::floor(u)); }

void mark_rows(OccupancyGrid& g, int64_t col, int64_t lo, int64_t hi, uint8_t value) {
  lo = std::max<int64_t>(lo, 0);
  hi = std::min<int64_t>(hi, g.height - 1);
  for (int64_t row = lo; row <= hi; ++row) g.set(col, row, value);
}

uint8_t pixel(uint8_t cell) {
  if (cell > 100) return 205;  // unknown
  if (cell >= 65) return 0;    // occupied_thresh 0.65
  if (cell <= 19) return 254;  // below free_thresh 0.196
  return 205;                  // neither: trinary has no shades
}

}  // namespace

OccupancyGrid make_grid(const Rect& r, double resolution, uint8_t fill) {
  if (!std::isfinite(resolution) || !(resolution > 0))
    throw std::invalid_argument("expected a finite resolution > 0 (m per cell), got " + format_number(resolution));
  if (!(r.xmin <= r.xmax && r.ymin <= r.ymax) || !std::isfinite(r.xmax - r.xmin) || !std::isfinite(r.ymax - r.ymin))
    throw std::invalid_argument("expected finite grid bounds");
  // The same expression as to_grid, so the cell of the upper-right corner is in the grid.
  const double w = std::floor((r.xmax - r.xmin) / resolution) + 1;
  const double h = std::floor((r.ymax - r.ymin) / resolution) + 1;
  if (w * h > kMaxGridCells)
    throw std::invalid_argument("expected an occupancy grid of at most " + format_number(kMaxGridCells) +
                                " cells, got " + format_number(w) + " x " + format_number(h) + " at " +
                                format_number(resolution) + " m per cell; choose a coarser resolution");
  OccupancyGrid g;
  g.resolution = resolution;
  g.origin = {r.xmin, r.ymin};
  g.width = static_cast<int>(w);
  g.height = static_cast<int>(h);
  g.cells.assign(static_cast<size_t>(g.width) * g.height, fill);
  return g;
}

Rect grid_bounds(const Map& map, double margin) {
  if (!map.border.rect().empty()) return map.border.rect();
  constexpr double inf = std::numeric_limits<double>::infinity();
  Rect r{inf, inf, -inf, -inf};
  for (const Obstacle& o : map.obstacles)
    for (const Segment& s : o.segments)
      for (Point p : {s.a, s.b}) r = {std::min(r.xmin, p.x), std::min(r.ymin, p.y), std::max(r.xmax, p.x), std::max(r.ymax, p.y)};
  if (r.xmin > r.xmax) throw std::invalid_argument("expected a map with a border or segments, got neither");
  return {r.xmin - margin, r.ymin - margin, r.xmax + margin, r.ymax + margin};
}

// Column by column: in column i the segment's points have x in [max(u0, i), min(u1, i+1)),
// the right end included only where the segment ends; their rows are the rows of that
// y interval with the same half-openness.
void draw_segment(OccupancyGrid& g, Point a, Point b, uint8_t value) {
  Point p = to_grid(g, a), q = to_grid(g, b);
  if (q.x < p.x) std::swap(p, q);
  const int64_t i0 = cell_index(p.x), i1 = cell_index(q.x);
  // y on the vertical grid line x = u, for p.x < u < q.x; one formula for both columns
  // that share the line, so they agree bit for bit.
  auto y_at = [&](double u) { return p.y + (q.y - p.y) * (u - p.x) / (q.x - p.x); };
  // From column -1: its corner rule may mark cells of column 0.
  const int64_t first = std::max<int64_t>(i0, -1), last = std::min<int64_t>(i1, g.width - 1);
  for (int64_t i = first; i <= last; ++i) {
    const double ya = i == i0 ? p.y : y_at(static_cast<double>(i));
    if (i == i1) {  // the segment ends in this column: both ends included
      mark_rows(g, i, cell_index(std::min(ya, q.y)), cell_index(std::max(ya, q.y)), value);
      continue;
    }
    const double yb = y_at(static_cast<double>(i + 1));
    if (yb > ya) mark_rows(g, i, cell_index(ya), static_cast<int64_t>(std::ceil(yb)) - 1, value);
    else mark_rows(g, i, cell_index(yb), cell_index(ya), value);
    // Through a corner (not at an end): the four cells around it.
    if (static_cast<double>(i + 1) < q.x && p.y != q.y && std::floor(yb) == yb) {
      const int64_t k = static_cast<int64_t>(yb);
      for (int64_t c : {i, i + 1})
        for (int64_t r : {k - 1, k}) g.set(c, r, value);
    }
  }
}

void fill_polygon(OccupancyGrid& g, const Polygon& ring, uint8_t value) {
  const size_t n = ring.size();
  if (n == 0) return;
  std::vector<Point> v(n);
  double vmin = std::numeric_limits<double>::infinity(), vmax = -vmin;
  for (size_t k = 0; k < n; ++k) {
    v[k] = to_grid(g, ring[k]);
    vmin = std::min(vmin, v[k].y);
    vmax = std::max(vmax, v[k].y);
  }
  // Scanlines through the cell centres (v = row + 0.5); crossings half-open in v.
  std::vector<double> xs;
  const int64_t r0 = std::max<int64_t>(0, cell_index(vmin - 0.5)), r1 = std::min<int64_t>(g.height - 1, cell_index(vmax));
  for (int64_t row = r0; row <= r1; ++row) {
    const double vc = static_cast<double>(row) + 0.5;
    xs.clear();
    for (size_t k = 0; k < n; ++k) {
      const Point s = v[k], t = v[(k + 1) % n];
      if ((s.y > vc) != (t.y > vc)) xs.push_back(s.x + (vc - s.y) / (t.y - s.y) * (t.x - s.x));
    }
    std::sort(xs.begin(), xs.end());
    for (size_t k = 0; k + 1 < xs.size(); k += 2) {
      // Columns whose centre i + 0.5 lies in [xs[k], xs[k+1]].
      const int64_t c0 = std::max<int64_t>(0, static_cast<int64_t>(std::ceil(xs[k] - 0.5)));
      const int64_t c1 = std::min<int64_t>(g.width - 1, cell_index(xs[k + 1] - 0.5));
      for (int64_t c = c0; c <= c1; ++c) g.set(c, row, value);
    }
  }
  // The outline: cells whose centre is on the boundary, and thin parts between centres.
  for (size_t k = 0; k < n; ++k) draw_segment(g, ring[k], ring[(k + 1) % n], value);
}

OccupancyGrid rasterize_map(const Map& map, double resolution) {
  OccupancyGrid g = make_grid(grid_bounds(map), resolution);
  for (const Obstacle& o : map.obstacles)
    for (const Segment& s : o.segments)
      if (!(o.type == ShapeType::Stairs && s.h == 0)) draw_segment(g, s.a, s.b);
  return g;
}

std::string pgm_raster(const OccupancyGrid& g) {
  std::string s(static_cast<size_t>(g.width) * g.height, '\0');
  for (int row = 0; row < g.height; ++row) {
    const size_t line = static_cast<size_t>(g.height - 1 - row) * g.width;  // top line = max y
    for (int col = 0; col < g.width; ++col) s[line + col] = static_cast<char>(pixel(g.at(col, row)));
  }
  return s;
}

std::string write_pgm(const OccupancyGrid& g) {
  return "P5\n" + std::to_string(g.width) + " " + std::to_string(g.height) + "\n255\n" + pgm_raster(g);
}

std::string write_nav2_yaml(const OccupancyGrid& g, const std::string& image_file_name) {
  std::string name;  // a double-quoted YAML scalar
  for (char c : image_file_name) {
    if (c == '"' || c == '\\') name += '\\';
    name += c;
  }
  return "image: \"" + name + "\"\nmode: trinary\nresolution: " + format_number(g.resolution) + "\norigin: [" +
         format_number(g.origin.x) + ", " + format_number(g.origin.y) +
         ", 0.0]\nnegate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n";
}

}  // namespace fleetmap
