#include "common/planning/map_planner.h"

#include <chrono>
#include <stdexcept>
#include <string>
#include <utility>

namespace fleetmap {

MapPlanner::MapPlanner(const Map& map, const PlannerOptions& options)
    : MapPlanner(map, prepare_planning_obstacles(map, options.robot), options) {}

MapPlanner::MapPlanner(const Map& map, PlanningObstacles obstacles, const PlannerOptions& options)
    : opt_(options), checker_(map, std::move(obstacles), ClearanceOptions{options.radius, options.robot, 0}) {
  opt_.rrt.seed = opt_.seed;
  if (opt_.attempts < 1) throw std::invalid_argument("expected at least 1 planning attempt, got " + std::to_string(opt_.attempts));
  RrtConnect check(checker_, opt_.rrt);  // validates the RRT options now, not at the first plan
}

PlanResult MapPlanner::plan(Point start, Point goal) const {
  const auto t0 = std::chrono::steady_clock::now();
  PlanResult r;
  if ((r.collision = checker_.collision(start))) {
    r.status = PlanStatus::StartBlocked;
    return r;
  }
  if ((r.collision = checker_.collision(goal))) {
    r.status = PlanStatus::GoalBlocked;
    return r;
  }
  // Each attempt's path is only shortcut (cheap, and enough to tell a long way round
  // from a short one); the corner cutting and rounding go to the shortest.
  const PathSmoother smoother(checker_, opt_.smoothing);
  double best = 0;
  for (int k = 0; k < opt_.attempts; ++k) {
    RrtOptions ro = opt_.rrt;
    ro.seed = opt_.seed + k;
    if (ro.max_time > 0) {  // one time limit for all the attempts
      ro.max_time -= std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      if (ro.max_time <= 0) break;
    }
    RrtConnect rrt(checker_, ro);
    std::optional<Path> raw = rrt.solve(start, goal);
    r.rrt.iterations += rrt.stats().iterations;
    r.rrt.start_tree += rrt.stats().start_tree;
    r.rrt.goal_tree += rrt.stats().goal_tree;
    r.rrt.seconds += rrt.stats().seconds;
    r.rrt.timed_out |= rrt.stats().timed_out;
    if (!raw) break;  // when one attempt fails, the next ones would most likely fail too
    const double len = path_length(opt_.smooth ? smoother.shortcut(*raw) : *raw);
    if (r.status != PlanStatus::Found || len < best) {
      r.status = PlanStatus::Found;
      r.raw = std::move(*raw);
      best = len;
    }
    if (r.raw.size() == 2) break;  // the straight line: nothing shorter
  }
  if (r.status == PlanStatus::Found) {
    r.path = opt_.smooth ? smoother.smooth(r.raw, &r.smoothing) : r.raw;
    r.length = path_length(*r.path);
  }
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

std::string_view to_string(PlanStatus s) {
  switch (s) {
    case PlanStatus::Found: return "found";
    case PlanStatus::StartBlocked: return "start blocked";
    case PlanStatus::GoalBlocked: return "goal blocked";
    case PlanStatus::NoPath: return "no path";
  }
  return "?";
}

}  // namespace fleetmap
