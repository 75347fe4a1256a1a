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

namespace {

// One cell's obstacles before culling: (distance from the cell's centre, id), sorted
// nearest first (ties by id, so that the build is deterministic).
using Keyed = std::pair<float, uint32_t>;

// The distances a list is built on, for an id of candidate_grid.h (a wall below
// `walls`, else a stair's or ramp's bounding box).
struct Distances {
  const LaserObstacles& obstacles;
  uint32_t walls;
  double to_cell2(uint32_t id, const Rect& c) const {
    if (id >= walls) return squared_distance(obstacles.specials[id - walls].bounds, c);
    const RaySegment& w = obstacles.walls[id];
    return squared_distance(w.a, w.a + w.e, c);
  }
  double to_point2(uint32_t id, Point p) const {
    if (id >= walls) return squared_distance(p, obstacles.specials[id - walls].bounds);
    const RaySegment& w = obstacles.walls[id];
    return point_segment_distance2(p, w.a, w.a + w.e);
  }
};

}  // namespace

// Turns a cell's sorted obstacles into its list, less the walls that one of the
// `occluders` nearest walls kept so far hides from the whole cell (occlusion.h). A kept
// occluder may itself be hidden by a nearer one only if it was not kept, so every drop
// is backed by a kept wall or by a chain of strictly nearer hiders ending at one.
class CandidateGrid::CellCuller {
 public:
  CellCuller(const LaserObstacles& obstacles, size_t occluders)
      : obstacles_(obstacles), walls_(static_cast<uint32_t>(obstacles.walls.size())), occluders_(occluders) {}

  void append(const Rect& rect, Point centre, std::span<const Keyed> sorted,
              std::vector<CandidateGrid::Candidate>& list) {
    // From any point of the cell, a thing at `key` from its centre is at least this far;
    // 1e-5 m covers the float's rounding (1e-6 relative at the few tens of metres of rmax).
    const double half_diagonal = (rect.xmax - rect.xmin) * std::sqrt(0.5);
    auto lower_bound = [&](float key) {
      const double v = key - half_diagonal - 1e-5 * (1 + key);
      return v > 0 ? std::nextafter(static_cast<float>(v), 0.0f) : 0.0f;
    };
    hiders_.clear();
    for (const auto& [key, id] : sorted) {
      Arc arc;  // specials: every direction (their cone in the sweep is wider than the box)
      if (id < walls_) {
        const RaySegment& w = obstacles_.walls[id];
        const Point a = w.a - centre, b = a + w.e;
        double lo = pseudo_angle(a), hi = pseudo_angle(b);
        if (cross(a, w.e) < 0) std::swap(lo, hi);
        if (hi < lo) hi += 4;
        const bool on_line = std::fabs(cross(a, w.e)) <= 1e-9 * (1 + dot(w.e, w.e));
        if (!on_line && hidden(w, lo, hi, rect)) continue;
        if (hiders_.size() < occluders_ && !on_line) hiders_.push_back({id, lo, hi});
        arc = arc_from_cell(rect, w);
      }
      list.push_back({id, lower_bound(key), arc.lo, arc.width});
    }
  }

 private:
  // A hider must cover, from the cell's centre, the whole angle the wall covers (what
  // hides() implies for the centre): a cheap filter on pseudo-angle intervals first.
  struct Hider {
    uint32_t id;
    double lo, hi;  // pseudo-angles from the centre, hi in [lo, lo + 2]
  };

  bool hidden(const RaySegment& w, double lo, double hi, const Rect& rect) const {
    constexpr double kSlack = 1e-6;  // pseudo-angle units, far above their rounding
    for (const Hider& h : hiders_) {
      const double shift = lo + kSlack < h.lo ? 4 : 0;
      if (h.lo - kSlack <= lo + shift && hi + shift <= h.hi + kSlack && hides(obstacles_.walls[h.id], w, rect))
        return true;
    }
    return false;
  }

  const LaserObstacles& obstacles_;
  uint32_t walls_;
  size_t occluders_;
  std::vector<Hider> hiders_;
};

CandidateGrid::CandidateGrid(const LaserObstacles& obstacles, double cell, double rmax, size_t max_bytes,
                             size_t occluders)
    : wall_count_(static_cast<uint32_t>(obstacles.walls.size())) {
  if (obstacles.obstacles.empty()) return;
  // Cells finer than kRootCell are built by halving a grid of them level by level
  // (docs/ray-casting.md, "The sweep on dense floors"): a cell's list is taken from its
  // parent's culled list, which holds every wall not hidden from the parent, hence from
  // the cell; a wall hidden from the parent stays backed in the cell by the same chain
  // of hiders. Each level costs the parent's short lists, not every wall within reach.
  // Without culling a list is every obstacle within reach: built directly, as cheap.
  double root = cell;
  if (occluders > 0)
    while (root * 2 <= kRootCell) root *= 2;
  while (estimate_bytes(obstacles, root, rmax) > max_bytes) root *= 2;
  const double reach = rmax + kPad;
  CellCuller culler(obstacles, occluders);
  build_root(obstacles, root, reach, culler);
  // A cell's list is part of its parent's: four times the parent level's entries bound
  // the next level's.
  while (frame_.cell / 2 >= cell &&
         4 * (sizeof(Candidate) * list_.size() + sizeof(uint32_t) * cells()) + sizeof(uint32_t) <= max_bytes)
    halve(obstacles, reach, culler);
  list_.shrink_to_fit();
}

void CandidateGrid::build_root(const LaserObstacles& obstacles, double cell, double reach, CellCuller& culler) {
  const double inv_cell = 1 / cell;
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
  const Distances dist{obstacles, wall_count_};
  std::vector<Entry> entries;
  entries.reserve(estimate_bytes(obstacles, cell, reach) / sizeof(Candidate));  // an upper bound
  // The cells near r's box within reach, keyed by their centre's distance.
  auto visit = [&](const Rect& r, uint32_t id) {
    const CellRange range = frame_.cells_covering({r.xmin - reach, r.ymin - reach, r.xmax + reach, r.ymax + reach});
    for (int iy = range.y0; iy <= range.y1; ++iy)
      for (int ix = range.x0; ix <= range.x1; ++ix) {
        if (dist.to_cell2(id, frame_.cell_rect(ix, iy)) > reach * reach) continue;
        entries.push_back({static_cast<uint32_t>(frame_.index(ix, iy)),
                           static_cast<float>(std::sqrt(dist.to_point2(id, frame_.centre(ix, iy)))), id});
      }
  };
  for (uint32_t i = 0; i < wall_count_; ++i) visit(segment_box(obstacles.walls[i]), i);
  for (uint32_t k = 0; k < obstacles.specials.size(); ++k) visit(obstacles.specials[k].bounds, wall_count_ + k);
  // Counting sort by cell, then each cell's short list by distance.
  std::vector<uint32_t> offsets(cells() + 1, 0);
  for (const Entry& e : entries) ++offsets[e.cell + 1];
  for (size_t c = 0; c < cells(); ++c) offsets[c + 1] += offsets[c];
  std::vector<Keyed> sorted(entries.size());
  {
    std::vector<uint32_t> next(offsets.begin(), offsets.end() - 1);
    for (const Entry& e : entries) sorted[next[e.cell]++] = {e.key, e.id};
  }
  entries = {};
  offsets_.assign(cells() + 1, 0);
  list_.reserve(sorted.size());
  for (int iy = 0; iy < frame_.height; ++iy)
    for (int ix = 0; ix < frame_.width; ++ix) {
      const size_t c = frame_.index(ix, iy);
      const std::span<Keyed> cell_sorted(sorted.data() + offsets[c], sorted.data() + offsets[c + 1]);
      std::sort(cell_sorted.begin(), cell_sorted.end());
      culler.append(frame_.cell_rect(ix, iy), frame_.centre(ix, iy), cell_sorted, list_);
      offsets_[c + 1] = static_cast<uint32_t>(list_.size());
    }
}

void CandidateGrid::halve(const LaserObstacles& obstacles, double reach, CellCuller& culler) {
  // The same origin and half the cell: each cell of the new level lies in one of the
  // old, and their edges are the same numbers (cell_rect multiplies by exact halves).
  GridFrame fine = frame_;
  fine.cell = frame_.cell / 2;
  fine.width = 2 * frame_.width;
  fine.height = 2 * frame_.height;
  const Distances dist{obstacles, wall_count_};
  std::vector<uint32_t> offsets(fine.cells() + 1, 0);
  std::vector<Candidate> list;
  list.reserve(2 * list_.size());
  std::vector<Keyed> keyed;
  for (int iy = 0; iy < fine.height; ++iy)
    for (int ix = 0; ix < fine.width; ++ix) {
      const Rect rect = fine.cell_rect(ix, iy);
      const Point centre = fine.centre(ix, iy);
      keyed.clear();
      for (const Candidate& p : near_cell(frame_.index(ix / 2, iy / 2)))
        if (dist.to_cell2(p.id, rect) <= reach * reach)
          keyed.push_back({static_cast<float>(std::sqrt(dist.to_point2(p.id, centre))), p.id});
      std::sort(keyed.begin(), keyed.end());
      culler.append(rect, centre, keyed, list);
      offsets[fine.index(ix, iy) + 1] = static_cast<uint32_t>(list.size());
    }
  frame_ = fine;
  offsets_ = std::move(offsets);
  list_ = std::move(list);
}

size_t CandidateGrid::memory_bytes() const {
  return sizeof(*this) + offsets_.capacity() * sizeof(uint32_t) + list_.capacity() * sizeof(Candidate);
}

}  // namespace fleetmap
