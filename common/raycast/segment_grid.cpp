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
    : cell_(cell), inv_cell_(1 / cell) {
  if (obstacles.obstacles.empty()) return;
  const Rect& b = obstacles.bounds;
  // One empty cell of margin all round: rays from outside enter through empty cells.
  const double w = b.xmax - b.xmin, h = b.ymax - b.ymin;
  while ((w / cell_ + 3) * (h / cell_ + 3) > kMaxCells) cell_ *= 2;
  inv_cell_ = 1 / cell_;
  corner_ = {b.xmin - cell_, b.ymin - cell_};
  nx_ = static_cast<int>(std::floor(w * inv_cell_)) + 3;
  ny_ = static_cast<int>(std::floor(h * inv_cell_)) + 3;
  cells_.assign(static_cast<size_t>(nx_) * ny_, Cell{});

  auto col = [&](double x) {
    return std::clamp(static_cast<int>(std::floor((x - corner_.x) * inv_cell_)), 0, nx_ - 1);
  };
  auto row = [&](double y) {
    return std::clamp(static_cast<int>(std::floor((y - corner_.y) * inv_cell_)), 0, ny_ - 1);
  };
  auto index = [&](int ix, int iy) { return static_cast<size_t>(iy) * nx_ + ix; };

  // Walls: every cell whose square grown by kCellPad meets the segment, column by
  // column: in each column, the rows between the segment's lowest and highest point there.
  std::vector<std::pair<uint32_t, uint32_t>> entries;  // (cell, wall)
  for (uint32_t i = 0; i < obstacles.walls.size(); ++i) {
    const RaySegment& s = obstacles.walls[i];
    const Point a = s.a, e = s.e;
    const double xlo = std::min(a.x, a.x + e.x) - kCellPad, xhi = std::max(a.x, a.x + e.x) + kCellPad;
    for (int ix = col(xlo); ix <= col(xhi); ++ix) {
      double u0 = 0, u1 = 1;
      if (e.x != 0) {
        const double x0 = corner_.x + ix * cell_ - kCellPad, x1 = x0 + cell_ + 2 * kCellPad;
        u0 = std::clamp((x0 - a.x) / e.x, 0.0, 1.0);
        u1 = std::clamp((x1 - a.x) / e.x, 0.0, 1.0);
      }
      const double y0 = a.y + u0 * e.y, y1 = a.y + u1 * e.y;
      for (int iy = row(std::min(y0, y1) - kCellPad); iy <= row(std::max(y0, y1) + kCellPad); ++iy)
        entries.emplace_back(static_cast<uint32_t>(index(ix, iy)), i);
    }
  }
  std::stable_sort(entries.begin(), entries.end(), [](const auto& l, const auto& r) { return l.first < r.first; });
  walls_.reserve(entries.size());
  for (size_t k = 0; k < entries.size();) {
    Cell& c = cells_[entries[k].first];
    c.walls_begin = static_cast<uint32_t>(walls_.size());
    const uint32_t id = entries[k].first;
    for (; k < entries.size() && entries[k].first == id; ++k) walls_.push_back(obstacles.walls[entries[k].second]);
    c.walls_end = static_cast<uint32_t>(walls_.size());
  }

  // Stairs and ramps: every cell that meets their bounding box.
  std::vector<std::vector<uint32_t>> lists(cells_.size());
  special_lists_.push_back(0);  // offset 0 means "none"
  for (uint32_t k = 0; k < obstacles.specials.size(); ++k) {
    const Rect& r = obstacles.specials[k].bounds;
    for (int iy = row(r.ymin - kCellPad); iy <= row(r.ymax + kCellPad); ++iy)
      for (int ix = col(r.xmin - kCellPad); ix <= col(r.xmax + kCellPad); ++ix) lists[index(ix, iy)].push_back(k);
  }
  for (size_t c = 0; c < lists.size(); ++c) {
    if (lists[c].empty()) continue;
    cells_[c].specials = static_cast<uint32_t>(special_lists_.size());
    special_lists_.push_back(static_cast<uint32_t>(lists[c].size()));
    special_lists_.insert(special_lists_.end(), lists[c].begin(), lists[c].end());
  }

  // Skip distances: the distance from the cell's centre to the nearest geometry, less
  // half the cell's diagonal (so it holds from any point of the cell), capped.
  std::vector<double> d2(cells_.size(), skip_cap * skip_cap);
  auto centre = [&](int ix, int iy) { return Point{corner_.x + (ix + 0.5) * cell_, corner_.y + (iy + 0.5) * cell_}; };
  for (const RaySegment& s : obstacles.walls) {
    const Point a = s.a, bb = s.a + s.e;
    for (int iy = row(std::min(a.y, bb.y) - skip_cap); iy <= row(std::max(a.y, bb.y) + skip_cap); ++iy)
      for (int ix = col(std::min(a.x, bb.x) - skip_cap); ix <= col(std::max(a.x, bb.x) + skip_cap); ++ix) {
        double& v = d2[index(ix, iy)];
        v = std::min(v, point_segment_distance2(centre(ix, iy), a, bb));
      }
  }
  for (const SpecialObstacle& sp : obstacles.specials) {
    const Rect& r = sp.bounds;
    for (int iy = row(r.ymin - skip_cap); iy <= row(r.ymax + skip_cap); ++iy)
      for (int ix = col(r.xmin - skip_cap); ix <= col(r.xmax + skip_cap); ++ix) {
        double& v = d2[index(ix, iy)];
        v = std::min(v, squared_distance(centre(ix, iy), r));
      }
  }
  const double half_diagonal = cell_ * std::sqrt(0.5);
  for (size_t c = 0; c < cells_.size(); ++c) {
    Cell& cl = cells_[c];
    if (cl.walls_begin != cl.walls_end || cl.specials != 0) continue;
    // Rounded down to a float, and a margin far above the rounding of either.
    const double skip = std::sqrt(d2[c]) - half_diagonal - 2 * kCellPad;
    // A skip too short to leave the cell only costs a step.
    cl.skip = skip > 0.01 * cell_ ? std::nextafter(static_cast<float>(skip), 0.0f) : 0.0f;
  }
}

size_t SegmentGrid::memory_bytes() const {
  return sizeof(*this) + cells_.capacity() * sizeof(Cell) + walls_.capacity() * sizeof(RaySegment) +
         special_lists_.capacity() * sizeof(uint32_t);
}

}  // namespace fleetmap
