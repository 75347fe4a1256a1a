#include "common/planning/goal_near.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

namespace fleetmap {
namespace {

double distance_to_footprints(Point p, const std::vector<Polygon>& footprints) {
  double d = std::numeric_limits<double>::infinity();
  for (const Polygon& f : footprints) d = std::min(d, distance_to_polygon(p, f));
  return d;
}

// Twice the signed area: > 0 for a counter-clockwise ring.
double signed_area2(const Polygon& ring) {
  double a = 0;
  for (size_t i = 1; i + 1 < ring.size(); ++i) a += cross(ring[i] - ring[0], ring[i + 1] - ring[0]);
  return a;
}

// The ring's outline grown by `offset`, sampled: along each edge moved outwards, and on
// the arc round each convex corner (a reflex corner's grown outline is where the two
// moved edges meet, which their samples already approach).
void sample_grown_ring(const Polygon& ring, double offset, double spacing, std::vector<Point>& out) {
  const size_t n = ring.size();
  const double orient = signed_area2(ring) > 0 ? 1 : -1;
  auto outward = [&](size_t i) {  // unit normal of edge i, pointing out of the ring
    const Point e = ring[(i + 1) % n] - ring[i];
    const double len = norm(e);
    return (orient / len) * Point{e.y, -e.x};
  };
  for (size_t i = 0; i < n; ++i) {
    const Point a = ring[i], b = ring[(i + 1) % n], nrm = outward(i);
    const size_t steps = std::max<size_t>(1, static_cast<size_t>(std::ceil(distance(a, b) / spacing)));
    for (size_t k = 0; k < steps; ++k) out.push_back(a + (static_cast<double>(k) / steps) * (b - a) + offset * nrm);
    // The corner at b, from this edge's normal to the next edge's, turning outwards.
    const Point next = outward((i + 1) % n);
    const double turn = std::atan2(cross(nrm, next), dot(nrm, next));  // signed angle
    if (orient * turn <= 0) continue;  // reflex or straight
    const size_t arc_steps = std::max<size_t>(1, static_cast<size_t>(std::ceil(std::fabs(turn) * offset / spacing)));
    const double a0 = std::atan2(nrm.y, nrm.x);
    for (size_t k = 0; k < arc_steps; ++k) {
      const double t = a0 + turn * static_cast<double>(k) / arc_steps;
      out.push_back(b + offset * Point{std::cos(t), std::sin(t)});
    }
  }
}

}  // namespace

std::vector<Point> points_beside(const std::vector<Polygon>& footprints, double offset, double spacing) {
  if (footprints.empty()) throw std::invalid_argument("expected at least one footprint");
  if (!(std::isfinite(offset) && offset > 0)) throw std::invalid_argument("expected an offset > 0");
  if (!(std::isfinite(spacing) && spacing > 0)) throw std::invalid_argument("expected a spacing > 0");
  std::vector<Point> samples;
  for (const Polygon& f : footprints) {
    if (f.size() < 3) throw std::invalid_argument("expected footprints of at least 3 vertices");
    sample_grown_ring(f, offset, spacing, samples);
  }
  // Keep the points on the union's grown outline: nearer than offset to some other part
  // means inside it (rounding allowed for).
  const double tol = 1e-9 * (1 + offset);
  std::vector<Point> out;
  for (Point p : samples)
    if (distance_to_footprints(p, footprints) >= offset - tol) out.push_back(p);
  return out;
}

GoalNear choose_goal_beside(const MapPlanner& planner, const std::vector<Polygon>& footprints, Point from,
                            const GoalNearOptions& options) {
  if (!(std::isfinite(options.margin) && options.margin > 0)) throw std::invalid_argument("expected a margin > 0");
  if (!(std::isfinite(options.spacing) && options.spacing > 0)) throw std::invalid_argument("expected a spacing > 0");
  if (options.max_candidates < 4 || options.max_plans < 1)
    throw std::invalid_argument("expected at least 4 candidates and 1 plan");
  GoalNear r;
  const ClearanceChecker& checker = planner.checker();
  if ((r.plan.collision = checker.collision(from))) {
    r.status = GoalNearStatus::StartBlocked;
    r.plan.status = PlanStatus::StartBlocked;
    return r;
  }
  const double offset = checker.radius() + options.margin;
  // Widen the spacing so that a large object gets at most max_candidates points: the
  // grown outline is no longer than the outlines plus one turn of 2 pi offset each.
  double perimeter = 0;
  for (const Polygon& f : footprints) {
    for (size_t i = 0; i < f.size(); ++i) perimeter += distance(f[i], f[(i + 1) % f.size()]);
    perimeter += 2 * std::numbers::pi * offset;
  }
  const double spacing = std::max(options.spacing, perimeter / static_cast<double>(options.max_candidates));

  std::vector<Point> candidates = points_beside(footprints, offset, spacing);
  r.candidates = candidates.size();
  std::erase_if(candidates, [&](Point p) { return !checker.point_clear(p); });
  r.free = candidates.size();
  if (candidates.empty()) return r;  // NoFreeSpot
  std::stable_sort(candidates.begin(), candidates.end(),
                   [&](Point a, Point b) { return distance(from, a) < distance(from, b); });
  r.status = GoalNearStatus::NoPath;
  for (Point c : candidates) {
    if (r.planned == options.max_plans) break;
    if (r.status == GoalNearStatus::Found && distance(from, c) >= r.plan.length) break;  // cannot be shorter
    PlanResult p = planner.plan(from, c);
    ++r.planned;
    if (p.status != PlanStatus::Found) {
      if (r.status != GoalNearStatus::Found) r.plan = std::move(p);
      continue;
    }
    if (r.status != GoalNearStatus::Found || p.length < r.plan.length) {
      r.status = GoalNearStatus::Found;
      r.goal = c;
      r.plan = std::move(p);
    }
  }
  return r;
}

std::string_view to_string(GoalNearStatus s) {
  switch (s) {
    case GoalNearStatus::Found: return "found";
    case GoalNearStatus::StartBlocked: return "start blocked";
    case GoalNearStatus::NoFreeSpot: return "no free spot beside the object";
    case GoalNearStatus::NoPath: return "no path to any free spot beside the object";
  }
  return "?";
}

}  // namespace fleetmap
