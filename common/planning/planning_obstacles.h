#pragma once
// What blocks a robot's motion on the map, by shape type (SPEC 7, seed 000 §3.1 and §4.2):
// the planner's counterpart of the laser rules in common/raycast/ray_rules.h.
//
//   ST 1-4  a segment with h > 0 blocks ("all obstacles o^k with h^k > 0", §4.2); a
//           segment with h = 0 (a painted line, a kerb drawn flat) does not.
//   ST 5    stairs: for a wheeled robot the staircase is an area to avoid ("step segments
//           define an obstacle area to be avoided for the planner (if wheeled robot!)",
//           §3.1): its convex hull blocks, outline and inside, the h = 0 closing segment
//           included as part of that outline. A robot that can climb stairs ignores them.
//   ST 6    ramps never block ("ramps will be treated as free space", §4.2).
//
// The border is handled by ClearanceChecker: a robot must stay inside it. Objects and
// avoided areas of the semantic layer are added by common/planning/planning_scene.h.
#include <map>
#include <string>
#include <vector>

#include "common/geometry/geometry.h"
#include "common/map/map.h"

namespace fleetmap {

struct BlockingSegment {
  Point a, b;
  int obstacle_id = 0;  // the map obstacle it comes from (for messages)
};

// An area a robot may not enter: a staircase's hull (convex, counter-clockwise), or an
// object's footprint or an avoided area (a simple ring, either orientation).
struct BlockedArea {
  std::vector<Point> ring;  // >= 3 vertices, not repeated at the end
  Rect bounds;
  int obstacle_id = 0;
  bool contains(Point p) const;  // inside or on the outline (exact, common/geometry/polygon.h)
};

struct PlanningObstacles {
  std::vector<BlockingSegment> segments;  // every segment a robot's disc may not touch
  std::vector<BlockedArea> areas;         // whose outlines are also in segments
  // What the ids that are not map obstacles stand for ("object:<tag>:<id>",
  // "avoid:<id>"), for messages.
  std::map<int, std::string> names;
};

// The ring as a BlockedArea with its bounds, and its outline appended to out.segments.
void add_blocked_area(PlanningObstacles& out, std::vector<Point> ring, int obstacle_id);

struct RobotKind {
  bool can_climb_stairs = false;  // false: a wheeled robot
};

PlanningObstacles prepare_planning_obstacles(const Map& map, const RobotKind& robot);

// Convex hull (Andrew's monotone chain), counter-clockwise, collinear points dropped.
std::vector<Point> convex_hull(std::vector<Point> points);

}  // namespace fleetmap
