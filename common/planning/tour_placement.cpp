#include "common/planning/tour_placement.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

namespace fleetmap {
namespace {

Point at(const TourPose& p) { return {p.x, p.y}; }

// A ray that reaches rmax (or max_width) met no wall.
bool is_hit(double range, const RayCaster& caster, const TourPlacementOptions& o) {
  return range < caster.options().rmax - 1e-9 && range < o.max_width;
}

}  // namespace

Placement centre_in_corridor(const RayCaster& caster, const TourPose& pose, const TourPlacementOptions& o) {
  const Point p = at(pose);
  Placement best{p, false, std::numeric_limits<double>::infinity()};
  const int steps = o.angle_step > 0 ? static_cast<int>(std::floor(o.corridor_spread / o.angle_step)) : 0;
  for (int i = -steps; i <= steps; ++i) {
    const Point d = ray_direction(pose.theta + std::numbers::pi / 2 + i * o.angle_step);
    const double left = caster.cast_direction(p, d);
    const double right = caster.cast_direction(p, -1.0 * d);
    if (!is_hit(left, caster, o) || !is_hit(right, caster, o)) continue;
    const double width = left + right;
    if (width < o.min_gap || width > o.max_width || width >= best.width) continue;
    best = {p + (0.5 * (left - right)) * d, true, width};
  }
  if (!best.measured) best.width = 0;
  return best;
}

Placement centre_in_doorway(const RayCaster& caster, const TourPose& pose, const TourPlacementOptions& o) {
  const Point p = at(pose);
  const Point h = ray_direction(pose.theta);
  const Point n{-h.y, h.x};  // left of the heading
  struct Hit {
    Point pt;
    double side;  // > 0 left of the heading line
  };
  std::vector<Hit> left, right;
  const int rays = std::max(o.door_rays, 8);
  for (int i = 0; i < rays; ++i) {
    const double range = caster.cast(p, pose.theta + 2 * std::numbers::pi * i / rays);
    if (!is_hit(range, caster, o)) continue;
    const Point pt = p + range * ray_direction(pose.theta + 2 * std::numbers::pi * i / rays);
    const double side = dot(pt - p, n);
    if (side > 1e-9) left.push_back({pt, side});
    else if (side < -1e-9) right.push_back({pt, side});
  }
  // How far the robot sees along its heading line, ahead and behind.
  const double ahead = caster.cast_direction(p, h), behind = caster.cast_direction(p, -1.0 * h);
  constexpr double kMargin = 0.05;  // metres: a crossing point on a wall is not free
  struct Chord {
    double len;
    Point mid;
  };
  std::vector<Chord> chords;
  for (const Hit& a : left) {
    for (const Hit& b : right) {
      const double len = distance(a.pt, b.pt);
      if (len < o.min_gap || len > o.max_width) continue;
      const Point c = a.pt + (a.side / (a.side - b.side)) * (b.pt - a.pt);
      const double s = dot(c - p, h);
      if (std::abs(s) > o.door_window) continue;
      if (s >= 0 ? s + kMargin > ahead : -s + kMargin > behind) continue;
      chords.push_back({len, 0.5 * (a.pt + b.pt)});
    }
  }
  std::sort(chords.begin(), chords.end(), [](const Chord& l, const Chord& r) { return l.len < r.len; });
  // Between two posts the posts are what is nearest to the middle: its clearance is half
  // the chord. A chord cutting a corner, or lying along a wall, has a wall much nearer.
  constexpr int kClearanceRays = 180;
  constexpr double kClearanceShare = 0.8;  // of the half chord; hits are samples of the posts
  for (const Chord& ch : chords) {
    double clearance = std::numeric_limits<double>::infinity();
    for (int i = 0; i < kClearanceRays && clearance >= kClearanceShare * 0.5 * ch.len; ++i)
      clearance = std::min(clearance, caster.cast(ch.mid, 2 * std::numbers::pi * i / kClearanceRays));
    if (clearance >= kClearanceShare * 0.5 * ch.len) return {ch.mid, true, ch.len};
  }
  return {p, false, 0};
}

Placement centre_in_crossing(const RayCaster& caster, const TourPose& pose, const TourPlacementOptions& o) {
  const Point p = at(pose);
  constexpr int kRays = 72;
  constexpr double kStep = 0.1;
  auto clearance = [&](Point q, double enough) {
    double c = std::numeric_limits<double>::infinity();
    for (int i = 0; i < kRays && c > enough; ++i) c = std::min(c, caster.cast(q, 2 * std::numbers::pi * i / kRays));
    return c;
  };
  const int n = static_cast<int>(std::floor(o.crossing_window / kStep));
  std::vector<std::pair<Point, double>> grid;  // point, clearance
  double most = 0;
  for (int i = -n; i <= n; ++i) {
    for (int j = -n; j <= n; ++j) {
      const Point q = p + Point{i * kStep, j * kStep};
      grid.emplace_back(q, clearance(q, -1));
      most = std::max(most, grid.back().second);
    }
  }
  if (!(most > 0) || !is_hit(most, caster, o)) return {p, false, 0};
  // Of the points within 1 cm of the most, the one nearest the pose (a corridor's
  // length has no single best point).
  Placement best{p, true, 2 * most};
  double nearest = std::numeric_limits<double>::infinity();
  for (const auto& [q, c] : grid)
    if (c >= most - 0.01 && distance(q, p) < nearest) nearest = distance(q, p), best.pos = q;
  return best;
}

}  // namespace fleetmap
