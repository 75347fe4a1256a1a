#pragma once
// Goals by meaning (seed 002 section 3.3): "go to the charging station" becomes a
// reachable point beside the object, chosen for the robot that will drive there.
//
//   1. Candidates on the object's outline grown by radius + margin: points offset
//      outwards from every edge of its footprints and on arcs round their convex
//      corners, kept only where the distance to the object (the nearest of its
//      footprints) is exactly that much, so none lies inside another of its parts.
//   2. Those where the robot's disc is clear (ClearanceChecker::point_clear: radius from
//      every wall, blocking object and avoided area, inside the border).
//   3. The one with the shortest planned path from the robot's pose. Candidates are
//      planned nearest first (straight-line distance) and the search stops when the
//      next one is farther in a straight line than the best path found, which no path
//      to it can beat; at most max_plans plans.
//
// With the planner the server uses (server/core/planner_cache.h) the goal is one GetPath
// will reach.
#include <cstddef>
#include <string_view>
#include <vector>

#include "common/planning/map_planner.h"
#include "common/geometry/polygon.h"

namespace fleetmap {

struct GoalNearOptions {
  double margin = 0.1;          // metres beyond the robot's radius, > 0
  double spacing = 0.1;         // metres between candidates along the grown outline, > 0
  size_t max_candidates = 256;  // spacing widens on large objects to keep to this many
  size_t max_plans = 32;        // planner runs at most (an unreachable object fails fast)
};

enum class GoalNearStatus {
  Found,
  StartBlocked,  // the robot's own pose is not clear
  NoFreeSpot,    // no candidate is clear: the object is walled in, or nothing is beside it
  NoPath,        // free candidates, but none reached
};

struct GoalNear {
  GoalNearStatus status = GoalNearStatus::NoFreeSpot;
  Point goal;              // when Found
  PlanResult plan;         // the path to goal (Found), or the planner's answer on the start
  size_t candidates = 0;   // on the grown outline
  size_t free = 0;         // of them clear for the robot
  size_t planned = 0;      // planner runs
};

// Points at `offset` from the union of the footprints, on its outline, about `spacing`
// apart (step 1 above; no clearance test). Footprints are simple rings (polygon.h).
std::vector<Point> points_beside(const std::vector<Polygon>& footprints, double offset, double spacing);

// Steps 1-3 for the robot of planner (its radius) at `from`. Throws std::invalid_argument
// for empty footprints or options out of range.
GoalNear choose_goal_beside(const MapPlanner& planner, const std::vector<Polygon>& footprints, Point from,
                            const GoalNearOptions& options = {});

std::string_view to_string(GoalNearStatus s);

}  // namespace fleetmap
