#include "common/planning/topo_planner.h"

#include <algorithm>
#include <chrono>
#include <limits>
#include <utility>

namespace fleetmap {

namespace {

using Clock = std::chrono::steady_clock;

double since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

}  // namespace

TopoPlanner::TopoPlanner(const MapPlanner& planner, const TopoGraph& graph, const TopoPlanOptions& options)
    : planner_(planner), graph_(graph), opt_(options) {
  if (opt_.candidates < 1) opt_.candidates = 1;
}

RouteOptions TopoPlanner::route_options() const {
  return {.avoid_stairs = !planner_.options().robot.can_climb_stairs, .radius = planner_.checker().radius()};
}

// Step 1. Nodes by distance; the first few clear ones that p sees, else the nearest
// clear one (its leg goes to RRT-Connect). Only the nearest 4k clear nodes are tried
// for sight: a motion check along a long line costs more than the graph search.
std::vector<TopoPlanner::Candidate> TopoPlanner::candidates(Point p) const {
  const ClearanceChecker& checker = planner_.checker();
  std::vector<std::pair<double, int>> by_distance;
  by_distance.reserve(graph_.nodes().size());
  for (const TopoNode& n : graph_.nodes()) by_distance.push_back({distance(p, n.pos), n.id});
  std::sort(by_distance.begin(), by_distance.end());
  std::vector<Candidate> seen;
  std::optional<Candidate> nearest_clear;
  size_t tried = 0;
  for (const auto& [d, id] : by_distance) {
    const Point q = graph_.node(id).pos;
    if (!checker.point_clear(q)) continue;
    if (!nearest_clear) nearest_clear = Candidate{id, d};
    if (checker.motion_clear(p, q)) seen.push_back({id, d});
    if (seen.size() >= opt_.candidates || ++tried >= 4 * opt_.candidates) break;
  }
  if (seen.empty() && nearest_clear) seen.push_back(*nearest_clear);
  return seen;
}

TopoPlanResult TopoPlanner::plan(Point start, Point goal) const {
  const auto t0 = Clock::now();
  const ClearanceChecker& checker = planner_.checker();
  TopoPlanResult r;
  auto done = [&](PlanStatus s) {
    r.status = s;
    r.seconds = since(t0);
    return r;
  };
  if ((r.collision = checker.collision(start))) return done(PlanStatus::StartBlocked);
  if ((r.collision = checker.collision(goal))) return done(PlanStatus::GoalBlocked);
  if (checker.motion_clear(start, goal)) {  // nothing to route round
    r.path = Path{start, goal};
    r.length = distance(start, goal);
    return done(PlanStatus::Found);
  }

  // Step 2: the best route over every pair of end candidates.
  const RouteOptions ro = route_options();
  double best = std::numeric_limits<double>::infinity();
  for (const Candidate& a : candidates(start))
    for (const Candidate& b : candidates(goal))
      if (std::optional<TopoRoute> route = graph_.route(a.node, b.node, ro)) {
        const double cost = a.cost + route->length + b.cost;
        if (cost < best) {
          best = cost;
          r.route = std::move(*route);
        }
      }
  if (r.route.nodes.empty()) return done(PlanStatus::NoPath);

  // Step 3: the legs. A node that is not clear for this radius (the graph was drawn for
  // another robot) is passed by the leg that skips it.
  Path stops{start};
  for (int id : r.route.nodes) {
    const Point q = graph_.node(id).pos;
    if (checker.point_clear(q) && q != stops.back()) stops.push_back(q);
  }
  if (goal != stops.back()) stops.push_back(goal);
  const PlannerOptions& po = planner_.options();
  const PathSmoother smoother(checker, po.smoothing);
  Path joined{start};
  for (size_t i = 1; i < stops.size(); ++i) {
    const Point a = stops[i - 1], b = stops[i];
    if (checker.motion_clear(a, b)) {
      joined.push_back(b);
      continue;
    }
    RrtOptions rrt = po.rrt;
    rrt.seed = po.seed + i;
    if (rrt.max_time > 0) {  // one time limit for all the legs, as MapPlanner's attempts
      rrt.max_time -= since(t0);
      if (rrt.max_time <= 0) return done(PlanStatus::NoPath);
    }
    RrtConnect solver(checker, rrt);
    const std::optional<Path> leg = solver.solve(a, b);
    if (!leg) return done(PlanStatus::NoPath);
    ++r.rrt_legs;
    const Path cut = po.smooth ? smoother.shortcut(*leg) : *leg;
    joined.insert(joined.end(), cut.begin() + 1, cut.end());
  }

  // Step 4.
  r.path = po.smooth ? smoother.smooth(joined) : joined;
  r.length = path_length(*r.path);
  return done(PlanStatus::Found);
}

}  // namespace fleetmap
