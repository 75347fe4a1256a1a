#pragma once
// Path planning on a map (SPEC 7, seed 000 §4.2): RRT-Connect between start and goal,
// then smoothing, for a disc robot of a given radius. One MapPlanner per map and robot
// (it builds the clearance index once); plan() may be called many times, and from
// several threads at once.
//
//   MapPlanner planner(map, {.radius = 0.3, .seed = 7});
//   MapPlanner with_objects(map, planning_obstacles(map, scene, body_height, {}), options);
//   PlanResult r = planner.plan({1, 2}, {40, 18});
//   if (r.path) use(*r.path, r.length);
#include <optional>
#include <string_view>

#include "common/planning/clearance_checker.h"
#include "common/map/map.h"
#include "common/planning/path.h"
#include "common/planning/path_smoother.h"
#include "common/planning/rrt_connect.h"

namespace fleetmap {

struct PlannerOptions {
  double radius = 0.3;  // metres
  uint64_t seed = 1;    // of RRT-Connect's samples (overrides rrt.seed)
  RobotKind robot;
  RrtOptions rrt;       // rrt.max_time limits all the attempts together
  SmoothingOptions smoothing;
  bool smooth = true;   // false: RRT-Connect's raw path
  // RRT-Connect runs (seeds seed, seed + 1, ...); the one whose shortcut path is shortest
  // is smoothed and kept. One run returns the first route the trees find, which may go
  // round a building on its long side; a few more cost little (bench-planner) and
  // usually find the short one. The first failed run ends the search.
  int attempts = 8;
};

enum class PlanStatus {
  Found,
  StartBlocked,  // the disc at the start is not clear (see PlanResult::collision)
  GoalBlocked,
  NoPath,        // the trees did not meet within the limits
};

struct PlanResult {
  PlanStatus status = PlanStatus::NoPath;
  std::optional<Path> path;  // the smoothed path, when found
  double length = 0;         // of *path, metres
  Path raw;                  // RRT-Connect's path before smoothing
  std::optional<Collision> collision;  // why start or goal is blocked
  RrtStats rrt;              // summed over the attempts
  SmoothingStats smoothing;  // of the path kept
  double seconds = 0;        // planning and smoothing
};

class MapPlanner {
 public:
  // Throws std::invalid_argument for options out of range.
  MapPlanner(const Map& map, const PlannerOptions& options);
  // With obstacles prepared elsewhere, e.g. a scene's objects and avoided areas
  // (common/planning/planning_scene.h); the map gives the border.
  MapPlanner(const Map& map, PlanningObstacles obstacles, const PlannerOptions& options);

  PlanResult plan(Point start, Point goal) const;
  const ClearanceChecker& checker() const { return checker_; }
  const PlannerOptions& options() const { return opt_; }

 private:
  PlannerOptions opt_;
  ClearanceChecker checker_;
};

std::string_view to_string(PlanStatus s);

}  // namespace fleetmap
