#include "common/planning/clearance_checker.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "common/geometry/segment_distance.h"

namespace fleetmap {
namespace {

// Metres: far above the rounding of coordinates below 1e7 (map_validation.h), far below
// anything a robot can tell apart; it only makes the index list a few cells more.
constexpr double kPad = 1e-6;
// A grid of more cells than this gets coarser cells (4 bytes of offset per cell).
constexpr double kMaxCells = 16.0 * 1024 * 1024;

double point_rect_distance2(Point p, const Rect& r) {
  const double dx = std::max({r.xmin - p.x, 0.0, p.x - r.xmax});
  const double dy = std::max({r.ymin - p.y, 0.0, p.y - r.ymax});
  return dx * dx + dy * dy;
}

// Squared distance between a closed rectangle and the segment ab: 0 when they meet,
// otherwise reached at an end of ab or at a corner of the rectangle (both convex).
double rect_segment_distance2(const Rect& r, Point a, Point b) {
  if (r.contains(a) || r.contains(b) || clip_segment(a, b, r)) return 0;
  double d2 = std::min(point_rect_distance2(a, r), point_rect_distance2(b, r));
  for (Point c : {Point{r.xmin, r.ymin}, Point{r.xmax, r.ymin}, Point{r.xmax, r.ymax}, Point{r.xmin, r.ymax}})
    d2 = std::min(d2, point_segment_distance2(c, a, b));
  return d2;
}

}  // namespace

ClearanceChecker::ClearanceChecker(const Map& map, const ClearanceOptions& options)
    : ClearanceChecker(map, prepare_planning_obstacles(map, options.robot), options) {}

ClearanceChecker::ClearanceChecker(const Map& map, PlanningObstacles obstacles, const ClearanceOptions& options)
    : radius_(options.radius), r2_(options.radius * options.radius), obstacles_(std::move(obstacles)) {
  if (!(std::isfinite(radius_) && radius_ >= 0))
    throw std::invalid_argument("expected a finite robot radius >= 0, got " + std::to_string(radius_));
  if (!(std::isfinite(options.cell) && options.cell >= 0))
    throw std::invalid_argument("expected a finite grid cell >= 0, got " + std::to_string(options.cell));
  const Rect border = map.border.rect();
  free_ = {border.xmin + radius_, border.ymin + radius_, border.xmax - radius_, border.ymax - radius_};
  if (!(free_.xmin <= free_.xmax && free_.ymin <= free_.ymax)) return;  // nowhere to stand

  double cell = options.cell > 0 ? options.cell : std::clamp(2 * radius_, 0.5, 2.0);
  const double w = free_.xmax - free_.xmin, h = free_.ymax - free_.ymin;
  if ((w / cell + 1) * (h / cell + 1) > kMaxCells) cell = std::sqrt(w * h / kMaxCells) + cell;
  const double inv_cell = 1 / cell;
  frame_ = {{free_.xmin, free_.ymin}, cell, static_cast<int>(std::floor(w * inv_cell)) + 1,
            static_cast<int>(std::floor(h * inv_cell)) + 1};

  // Every segment goes into every cell whose closed square is within r of it (plus
  // kPad): a centre nearer than r to the segment lies in one of those cells.
  const double reach = radius_ + kPad, reach2 = reach * reach;
  std::vector<std::pair<uint32_t, uint32_t>> pairs;  // (cell, segment)
  for (uint32_t i = 0; i < obstacles_.segments.size(); ++i) {
    const BlockingSegment& s = obstacles_.segments[i];
    frame_.for_cells_near_segment(s.a, s.b, reach, [&](int ix, int iy) {
      if (rect_segment_distance2(frame_.cell_rect(ix, iy), s.a, s.b) <= reach2)
        pairs.emplace_back(static_cast<uint32_t>(frame_.index(ix, iy)), i);
      return true;
    });
  }
  // Counting sort by cell: one contiguous block of entries per cell.
  begin_.assign(frame_.cells() + 1, 0);
  for (const auto& [c, i] : pairs) ++begin_[c + 1];
  for (size_t c = 1; c < begin_.size(); ++c) begin_[c] += begin_[c - 1];
  entries_.resize(pairs.size());
  std::vector<uint32_t> next(begin_.begin(), begin_.end() - 1);
  for (const auto& [c, i] : pairs) {
    const BlockingSegment& s = obstacles_.segments[i];
    entries_[next[c]++] = {s.a, s.b, i};
  }
}

bool ClearanceChecker::inside_area(Point p) const {
  for (const BlockedArea& area : obstacles_.areas)
    if (area.contains(p)) return true;
  return false;
}

bool ClearanceChecker::point_clear(Point p) const {
  if (!free_.contains(p) || inside_area(p)) return false;
  const size_t c = cell_of(p);
  for (uint32_t k = begin_[c]; k < begin_[c + 1]; ++k)
    if (point_segment_distance2(p, entries_[k].a, entries_[k].b) <= r2_) return false;
  return true;
}

bool ClearanceChecker::motion_clear(Point a, Point b) const {
  // The free rectangle is convex: both ends inside keep the whole motion inside. An area
  // is entered only across its outline, which is among the segments.
  if (!free_.contains(a) || !free_.contains(b) || inside_area(a)) return false;
  // A segment listed in several cells may be tested more than once; that costs less
  // than remembering which were tested.
  return frame_.for_cells_near_segment(a, b, kPad, [&](int ix, int iy) {
    const size_t c = frame_.index(ix, iy);
    for (uint32_t k = begin_[c]; k < begin_[c + 1]; ++k)
      if (segment_distance2(a, b, entries_[k].a, entries_[k].b) <= r2_) return false;
    return true;
  });
}

std::optional<Collision> ClearanceChecker::collision(Point p) const {
  if (!free_.contains(p)) return Collision{Collision::Kind::Border, 0};
  for (const BlockedArea& area : obstacles_.areas)
    if (area.contains(p)) return Collision{Collision::Kind::Area, area.obstacle_id};
  const size_t c = cell_of(p);
  for (uint32_t k = begin_[c]; k < begin_[c + 1]; ++k)
    if (point_segment_distance2(p, entries_[k].a, entries_[k].b) <= r2_)
      return Collision{Collision::Kind::Segment, obstacles_.segments[entries_[k].segment].obstacle_id};
  return std::nullopt;
}

size_t ClearanceChecker::memory_bytes() const {
  size_t areas = 0;
  for (const BlockedArea& a : obstacles_.areas) areas += sizeof(a) + a.ring.capacity() * sizeof(Point);
  return sizeof(*this) + begin_.capacity() * sizeof(uint32_t) + entries_.capacity() * sizeof(Entry) +
         obstacles_.segments.capacity() * sizeof(BlockingSegment) + areas;
}

}  // namespace fleetmap
