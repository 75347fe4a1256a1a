#include "common/planning/grid_astar.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>
#include <stdexcept>
#include <string>

#include "common/planning/clearance_checker.h"

namespace fleetmap {
namespace {

constexpr double kMaxCells = 64.0 * 1024 * 1024;
constexpr double kSqrt2 = 1.41421356237309504880;
constexpr int kDx[8] = {1, -1, 0, 0, 1, 1, -1, -1};
constexpr int kDy[8] = {0, 0, 1, -1, 1, -1, 1, -1};

}  // namespace

GridAStar::GridAStar(const Map& map, const GridAStarOptions& options) : res_(options.resolution) {
  if (!(std::isfinite(res_) && res_ > 0))
    throw std::invalid_argument("expected a grid resolution > 0 (metres), got " + std::to_string(res_));
  if (!(std::isfinite(options.radius) && options.radius >= 0))
    throw std::invalid_argument("expected a robot radius >= 0, got " + std::to_string(options.radius));
  const Rect b = map.border.rect();
  const double cols = std::ceil((b.xmax - b.xmin) / res_), rows = std::ceil((b.ymax - b.ymin) / res_);
  if (cols * rows > kMaxCells)
    throw std::invalid_argument("expected a grid of at most 64 M cells, got " + std::to_string(cols * rows) +
                                " at resolution " + std::to_string(res_) + " m");
  frame_ = {{b.xmin, b.ymin}, res_, std::max(1, static_cast<int>(cols)), std::max(1, static_cast<int>(rows))};
  nx_ = frame_.width;
  const size_t n = frame_.cells();

  const ClearanceChecker inflated(map, {options.radius + res_ * std::sqrt(0.5), options.robot, 0});
  free_.resize(n);
  for (size_t c = 0; c < n; ++c) free_[c] = inflated.point_clear(centre(static_cast<uint32_t>(c)));
  g_.resize(n);
  stamp_.assign(n, 0);
  came_from_.resize(n);
  closed_.resize(n);
}

size_t GridAStar::free_cells() const { return static_cast<size_t>(std::count(free_.begin(), free_.end(), 1)); }

Point GridAStar::centre(uint32_t c) const { return frame_.centre(c % nx_, c / nx_); }

std::optional<uint32_t> GridAStar::cell_of(Point p) const {
  const std::optional<size_t> c = frame_.index_of(p);
  if (!c || !free_[*c]) return std::nullopt;
  return static_cast<uint32_t>(*c);
}

std::optional<Path> GridAStar::solve(Point start, Point goal) {
  expanded_ = 0;
  const auto s = cell_of(start), t = cell_of(goal);
  if (!s || !t) return std::nullopt;
  if (++run_ == 0) {  // the stamps wrapped around: forget them all
    std::fill(stamp_.begin(), stamp_.end(), 0);
    run_ = 1;
  }
  const int tx = *t % nx_, ty = *t / nx_;
  auto h = [&](uint32_t c) {  // octile distance, metres
    const double dx = std::abs(static_cast<int>(c % nx_) - tx), dy = std::abs(static_cast<int>(c / nx_) - ty);
    return res_ * (std::max(dx, dy) + (kSqrt2 - 1) * std::min(dx, dy));
  };
  struct Open {
    double f, g;
    uint32_t c;
    // Smallest f first; among equal f the deepest (largest g), which expands fewer cells.
    bool operator<(const Open& o) const { return f > o.f || (f == o.f && g < o.g); }
  };
  std::priority_queue<Open> open;
  auto touch = [&](uint32_t c) {
    if (stamp_[c] != run_) {
      stamp_[c] = run_;
      g_[c] = std::numeric_limits<float>::infinity();
      closed_[c] = 0;
    }
  };
  touch(*s);
  g_[*s] = 0;
  came_from_[*s] = 8;
  open.push({h(*s), 0, *s});
  bool found = false;
  while (!open.empty()) {
    const Open top = open.top();
    open.pop();
    if (closed_[top.c]) continue;  // a stale entry
    closed_[top.c] = 1;
    ++expanded_;
    if (top.c == *t) {
      found = true;
      break;
    }
    const int x = top.c % nx_, y = top.c / nx_;
    for (int k = 0; k < 8; ++k) {
      const int x2 = x + kDx[k], y2 = y + kDy[k];
      if (!frame_.inside(x2, y2)) continue;
      const uint32_t c2 = static_cast<uint32_t>(y2) * nx_ + x2;
      if (!free_[c2]) continue;
      touch(c2);
      if (closed_[c2]) continue;
      const double g2 = top.g + res_ * (k < 4 ? 1.0 : kSqrt2);
      if (g2 < g_[c2]) {
        g_[c2] = static_cast<float>(g2);
        came_from_[c2] = static_cast<uint8_t>(k);
        open.push({g2 + h(c2), g2, c2});
      }
    }
  }
  if (!found) return std::nullopt;
  Path path{goal};
  for (uint32_t c = *t;;) {
    path.push_back(centre(c));
    const uint8_t k = came_from_[c];
    if (k == 8) break;
    c = static_cast<uint32_t>(static_cast<int>(c) - kDx[k] - kDy[k] * nx_);
  }
  path.push_back(start);
  std::reverse(path.begin(), path.end());
  // Drop the centres in the middle of straight runs: same points, fewer of them.
  Path out{path.front()};
  for (size_t i = 1; i + 1 < path.size(); ++i)
    if (cross(path[i] - out.back(), path[i + 1] - path[i]) != 0 || dot(path[i] - out.back(), path[i + 1] - path[i]) <= 0)
      out.push_back(path[i]);
  out.push_back(path.back());
  return out;
}

}  // namespace fleetmap
