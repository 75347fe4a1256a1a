#include "common/raycast/segment_grid.h"

#include <algorithm>
#include <cmath>

#include "common/geometry/rect_distance.h"

namespace fleetmap {
namespace {

// A grid of more cells than this gets coarser cells instead (16 bytes a cell: 128 MiB).
constexpr double kMaxCells = 8.0 * 1024 * 1024;

}  // namespace

SegmentGrid::SegmentGrid(const LaserObstacles& obstacles, double cell, double skip_cap)
    : inv_cell_(1 / cell) {
  frame_.cell = cell;
  if (obstacles.obstacles.empty()) return;
  const Rect& b = obstacles.bounds;
  // One empty cell of margin all round: rays from outside enter through empty cells.
  const double w = b.xmax - b.xmin, h = b.ymax - b.ymin;
  double& c = frame_.cell;
  while ((w / c + 3) * (h / c + 3) > kMaxCells) c *= 2;
  inv_cell_ = 1 / c;
  frame_.origin = {b.xmin - c, b.ymin - c};
  frame_.width = static_cast<int>(std::floor(w * inv_cell_)) + 3;
  frame_.height = static_cast<int>(std::floor(h * inv_cell_)) + 3;
  cells_.assign(frame_.cells(), Cell{});

  // Walls: every cell whose square grown by kCellPad meets the segment.
  std::vector<std::pair<uint32_t, uint32_t>> entries;  // (cell, wall)
  for (uint32_t i = 0; i < obstacles.walls.size(); ++i) {
    const RaySegment& s = obstacles.walls[i];
    frame_.for_cells_near_segment(s.a, s.a + s.e, kCellPad, [&](int ix, int iy) {
      entries.emplace_back(static_cast<uint32_t>(frame_.index(ix, iy)), i);
      return true;
    });
  }
  std::stable_sort(entries.begin(), entries.end(), [](const auto& l, const auto& r) { return l.first < r.first; });
  walls_.reserve(entries.size());
  for (size_t k = 0; k < entries.size();) {
    Cell& cl = cells_[entries[k].first];
    cl.walls_begin = static_cast<uint32_t>(walls_.size());
    const uint32_t id = entries[k].first;
    for (; k < entries.size() && entries[k].first == id; ++k) walls_.push_back(obstacles.walls[entries[k].second]);
    cl.walls_end = static_cast<uint32_t>(walls_.size());
  }

  auto grown = [](const Rect& r, double by) { return Rect{r.xmin - by, r.ymin - by, r.xmax + by, r.ymax + by}; };
  auto for_cells = [&](const Rect& r, auto&& f) {
    const CellRange range = frame_.cells_covering(r);
    for (int iy = range.y0; iy <= range.y1; ++iy)
      for (int ix = range.x0; ix <= range.x1; ++ix) f(ix, iy);
  };

  // Stairs and ramps: every cell that meets their bounding box.
  std::vector<std::vector<uint32_t>> lists(cells_.size());
  special_lists_.push_back(0);  // offset 0 means "none"
  for (uint32_t k = 0; k < obstacles.specials.size(); ++k)
    for_cells(grown(obstacles.specials[k].bounds, kCellPad), [&](int ix, int iy) { lists[frame_.index(ix, iy)].push_back(k); });
  for (size_t i = 0; i < lists.size(); ++i) {
    if (lists[i].empty()) continue;
    cells_[i].specials = static_cast<uint32_t>(special_lists_.size());
    special_lists_.push_back(static_cast<uint32_t>(lists[i].size()));
    special_lists_.insert(special_lists_.end(), lists[i].begin(), lists[i].end());
  }

  // Skip distances: the distance from the cell's centre to the nearest geometry, less
  // half the cell's diagonal (so it holds from any point of the cell), capped.
  std::vector<double> d2(cells_.size(), skip_cap * skip_cap);
  for (const RaySegment& s : obstacles.walls) {
    const Point a = s.a, bb = s.a + s.e;
    const Rect box{std::min(a.x, bb.x), std::min(a.y, bb.y), std::max(a.x, bb.x), std::max(a.y, bb.y)};
    for_cells(grown(box, skip_cap), [&](int ix, int iy) {
      double& v = d2[frame_.index(ix, iy)];
      v = std::min(v, point_segment_distance2(frame_.centre(ix, iy), a, bb));
    });
  }
  for (const SpecialObstacle& sp : obstacles.specials) {
    const Rect& r = sp.bounds;
    for_cells(grown(r, skip_cap), [&](int ix, int iy) {
      double& v = d2[frame_.index(ix, iy)];
      v = std::min(v, squared_distance(frame_.centre(ix, iy), r));
    });
  }
  const double half_diagonal = c * std::sqrt(0.5);
  for (size_t i = 0; i < cells_.size(); ++i) {
    Cell& cl = cells_[i];
    if (cl.walls_begin != cl.walls_end || cl.specials != 0) continue;
    // Rounded down to a float, and a margin far above the rounding of either.
    const double skip = std::sqrt(d2[i]) - half_diagonal - 2 * kCellPad;
    // A skip too short to leave the cell only costs a step.
    cl.skip = skip > 0.01 * c ? std::nextafter(static_cast<float>(skip), 0.0f) : 0.0f;
  }
}

size_t SegmentGrid::memory_bytes() const {
  return sizeof(*this) + cells_.capacity() * sizeof(Cell) + walls_.capacity() * sizeof(RaySegment) +
         special_lists_.capacity() * sizeof(uint32_t);
}

}  // namespace fleetmap
