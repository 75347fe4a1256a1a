#include "common/raycast/candidate_grid.h"

#include <algorithm>
#include <cmath>

#include "common/geometry/rect_distance.h"
#include "common/raycast/beam_order.h"
#include "common/raycast/occlusion.h"

namespace fleetmap {
namespace {

Rect segment_box(const RaySegment& s) {
  const Point b = s.a + s.e;
  return {std::min(s.a.x, b.x), std::min(s.a.y, b.y), std::max(s.a.x, b.x), std::max(s.a.y, b.y)};
}

struct Arc {
  float lo = 0, width = 4;  // pseudo-angles: every direction
};

// The pseudo-angle arc that holds every direction from a point of the cell (grown by
// kArcMargin) to a point of the wall (lengthened by it, beyond the exact test's
// tolerance), widened by kArcSlack: more than the sweep's slack on a wall's interval and
// than float rounding. Those directions are those of the points of the convex polygon
// wall - cell, within the arc of its eight vertices when it does not hold the origin;
// when it does (an arc of 2 or more, half a turn), every direction.
Arc arc_from_cell(const Rect& cell, const RaySegment& w) {
  constexpr double kArcMargin = 1e-6;  // metres
  constexpr double kArcSlack = 1e-4;   // pseudo-angle units
  const double len = std::sqrt(dot(w.e, w.e));
  if (len == 0) return {};
  const Point u = (kArcMargin / len) * w.e;
  const Point ends[2] = {w.a - u, w.a + w.e + u};
  const double m = kArcMargin;
  const Point corners[4] = {
      {cell.xmin - m, cell.ymin - m}, {cell.xmax + m, cell.ymin - m}, {cell.xmin - m, cell.ymax + m},
      {cell.xmax + m, cell.ymax + m}};
  const double p0 = pseudo_angle(ends[0] - corners[0]);
  double lo = 0, hi = 0;
  for (const Point& q : ends)
    for (const Point& p : corners) {
      double d = pseudo_angle(q - p) - p0;  // in (-4, 4): to (-2, 2]
      if (d > 2) d -= 4;
      if (d <= -2) d += 4;
      lo = std::min(lo, d);
      hi = std::max(hi, d);
    }
  if (hi - lo >= 2 - 2 * kArcSlack) return {};
  double start = p0 + lo - kArcSlack;
  if (start < 0) start += 4;
  if (start >= 4) start -= 4;
  return {std::nextafter(static_cast<float>(start), 0.0f),
          std::nextafter(static_cast<float>(hi - lo + 2 * kArcSlack), 5.0f)};
}

}  // namespace

double CandidateGrid::estimate_mean_list(const LaserObstacles& obstacles, double cell, double rmax) {
  const Rect& b = obstacles.bounds;
  if (obstacles.obstacles.empty()) return 0;
  const double cells = ((b.xmax - b.xmin + 2 * rmax) / cell + 3) * ((b.ymax - b.ymin + 2 * rmax) / cell + 3);
  return (estimate_bytes(obstacles, cell, rmax) - sizeof(uint32_t) * cells) / sizeof(Candidate) / cells;
}

size_t CandidateGrid::estimate_bytes(const LaserObstacles& obstacles, double cell, double rmax) {
  // Each wall's bounding box grown by rmax, in cells: an upper bound of its entries.
  double entries = 0;
  auto add = [&](const Rect& r) {
    entries += ((r.xmax - r.xmin + 2 * rmax) / cell + 2) * ((r.ymax - r.ymin + 2 * rmax) / cell + 2);
  };
  for (const RaySegment& s : obstacles.walls) add(segment_box(s));
  for (const SpecialObstacle& sp : obstacles.specials) add(sp.bounds);
  const Rect& b = obstacles.bounds;
  const double cells = obstacles.obstacles.empty()
                           ? 0
                           : ((b.xmax - b.xmin + 2 * rmax) / cell + 3) * ((b.ymax - b.ymin + 2 * rmax) / cell + 3);
  return static_cast<size_t>(std::min(sizeof(Candidate) * entries + sizeof(uint32_t) * cells, 1e18));
}

CandidateGrid::CandidateGrid(const LaserObstacles& obstacles, double cell, double rmax, size_t max_bytes,
                             size_t occluders)
    : wall_count_(static_cast<uint32_t>(obstacles.walls.size())) {
  if (obstacles.obstacles.empty()) return;
  while (estimate_bytes(obstacles, cell, rmax) > max_bytes) cell *= 2;
  const double inv_cell = 1 / cell;
  const double reach = rmax + kPad;
  const Rect& b = obstacles.bounds;
  frame_.cell = cell;
  frame_.origin = {b.xmin - reach - cell, b.ymin - reach - cell};
  frame_.width = static_cast<int>(std::floor((b.xmax - b.xmin + 2 * reach) * inv_cell)) + 3;
  frame_.height = static_cast<int>(std::floor((b.ymax - b.ymin + 2 * reach) * inv_cell)) + 3;

  struct Entry {
    uint32_t cell;
    float key;  // distance from the cell's centre: nearest first
    uint32_t id;
  };
  // From any point of the cell, a thing at `key` from its centre is at least this far;
  // 1e-5 m covers the float's rounding (1e-6 relative at the few tens of metres of rmax).
  const double half_diagonal = cell * std::sqrt(0.5);
  auto lower_bound = [&](float key) {
    const double v = key - half_diagonal - 1e-5 * (1 + key);
    return v > 0 ? std::nextafter(static_cast<float>(v), 0.0f) : 0.0f;
  };
  std::vector<Entry> entries;
  entries.reserve(estimate_bytes(obstacles, cell, rmax) / sizeof(Candidate));  // an upper bound
  // The cells near r's box that dist2_to_cell puts within reach, keyed by dist2_to_centre.
  auto visit = [&](const Rect& r, uint32_t id, auto&& dist2_to_cell, auto&& dist2_to_centre) {
    const CellRange range = frame_.cells_covering({r.xmin - reach, r.ymin - reach, r.xmax + reach, r.ymax + reach});
    for (int iy = range.y0; iy <= range.y1; ++iy)
      for (int ix = range.x0; ix <= range.x1; ++ix) {
        if (dist2_to_cell(frame_.cell_rect(ix, iy)) > reach * reach) continue;
        entries.push_back({static_cast<uint32_t>(frame_.index(ix, iy)),
                           static_cast<float>(std::sqrt(dist2_to_centre(frame_.centre(ix, iy)))), id});
      }
  };
  for (uint32_t i = 0; i < wall_count_; ++i) {
    const Point a = obstacles.walls[i].a, bb = a + obstacles.walls[i].e;
    visit(
        segment_box(obstacles.walls[i]), i, [&](const Rect& c) { return squared_distance(a, bb, c); },
        [&](Point p) { return point_segment_distance2(p, a, bb); });
  }
  for (uint32_t k = 0; k < obstacles.specials.size(); ++k) {
    const Rect& r = obstacles.specials[k].bounds;
    visit(
        r, wall_count_ + k, [&](const Rect& c) { return squared_distance(r, c); },
        [&](Point p) { return squared_distance(p, r); });
  }
  // Counting sort by cell, then each cell's short list by distance (ties by id, so
  // the build is deterministic).
  offsets_.assign(cells() + 1, 0);
  for (const Entry& e : entries) ++offsets_[e.cell + 1];
  for (size_t c = 0; c < cells(); ++c) offsets_[c + 1] += offsets_[c];
  std::vector<std::pair<float, uint32_t>> sorted(entries.size());
  {
    std::vector<uint32_t> next(offsets_.begin(), offsets_.end() - 1);
    for (const Entry& e : entries) sorted[next[e.cell]++] = {e.key, e.id};
  }
  entries = {};
  for (size_t c = 0; c < cells(); ++c) std::sort(sorted.begin() + offsets_[c], sorted.begin() + offsets_[c + 1]);
  list_.reserve(sorted.size());
  // Occlusion culling (occlusion.h), when occluders > 0: a wall hidden from the whole
  // cell by one of the nearest walls kept so far is left out. A kept occluder may itself
  // be hidden by a nearer one only if it was not kept, so every drop is backed by a kept
  // wall or by a chain of strictly nearer hiders ending at one.
  std::vector<uint32_t> kept_offsets(cells() + 1, 0);
  // A hider must cover, from the cell's centre, the whole angle the wall covers (what
  // hides() implies for the centre): a cheap filter on pseudo-angle intervals first.
  struct Hider {
    uint32_t id;
    double lo, hi;  // pseudo-angles from the centre, hi in [lo, lo + 2]
  };
  std::vector<Hider> hiders;
  constexpr double kSlack = 1e-6;  // pseudo-angle units, far above their rounding
  for (int iy = 0; iy < frame_.height; ++iy)
    for (int ix = 0; ix < frame_.width; ++ix) {
      const size_t c = frame_.index(ix, iy);
      const Rect rect = frame_.cell_rect(ix, iy);
      const Point centre = frame_.centre(ix, iy);
      hiders.clear();
      for (uint32_t k = offsets_[c]; k < offsets_[c + 1]; ++k) {
        const auto [key, id] = sorted[k];
        Arc arc;  // specials: every direction (their cone in the sweep is wider than the box)
        if (id < wall_count_) {
          const RaySegment& w = obstacles.walls[id];
          const Point a = w.a - centre, b = a + w.e;
          double lo = pseudo_angle(a), hi = pseudo_angle(b);
          if (cross(a, w.e) < 0) std::swap(lo, hi);
          if (hi < lo) hi += 4;
          const bool on_line = std::fabs(cross(a, w.e)) <= 1e-9 * (1 + dot(w.e, w.e));
          bool hidden = false;
          if (!on_line && occluders > 0)
            for (const Hider& h : hiders) {
              const double shift = lo + kSlack < h.lo ? 4 : 0;
              if (h.lo - kSlack <= lo + shift && hi + shift <= h.hi + kSlack &&
                  hides(obstacles.walls[h.id], w, rect)) {
                hidden = true;
                break;
              }
            }
          if (hidden) continue;
          if (hiders.size() < occluders && !on_line) hiders.push_back({id, lo, hi});
          arc = arc_from_cell(rect, w);
        }
        list_.push_back({id, lower_bound(key), arc.lo, arc.width});
      }
      kept_offsets[c + 1] = static_cast<uint32_t>(list_.size());
    }
  offsets_ = std::move(kept_offsets);
  list_.shrink_to_fit();
}

size_t CandidateGrid::memory_bytes() const {
  return sizeof(*this) + offsets_.capacity() * sizeof(uint32_t) + list_.capacity() * sizeof(Candidate);
}

}  // namespace fleetmap
