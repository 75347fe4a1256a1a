#pragma once
// Objects and avoided areas as planning obstacles (seed 002 section 3.3): the
// planner's counterpart of common/slicing/scene_laser.h.
//
//   element     blocks when the robot's body cannot pass over it, Element::blocks_body:
//               2D elements, and every element whose range starts below the body's top
//               (a table's legs block, its top 0.72..0.76 m blocks only a robot taller
//               than 0.72 m).
//   avoided     every avoided area blocks, whatever its height: no robot may enter it.
//
// Each blocking footprint or avoided area is a closed area (BlockedArea): its outline
// joins the blocking segments, so the robot's disc keeps its radius from it, and its
// inside is refused too, so a start or goal deep inside a large keep-out zone is
// blocked, not only one near its edge. The map's own obstacles block as before
// (common/planning/planning_obstacles.h).
//
//   MapPlanner planner(map, planning_obstacles(map, scene, body_height, robot), options);
#include "common/map/map.h"
#include "common/planning/planning_obstacles.h"
#include "common/scene/scene.h"

namespace fleetmap {

// The map's obstacles (prepare_planning_obstacles) and the scene's blocking elements and
// avoided areas. Scene items get obstacle ids after the map's largest, one per element
// or area, named in PlanningObstacles::names as "object:<tag>:<id>" or "avoid:<id>".
// Throws std::invalid_argument for a footprint or area that polygon_problem refuses,
// naming the object or area, or for a body height that is negative or not finite.
PlanningObstacles planning_obstacles(const Map& map, const Scene& scene, double body_height, const RobotKind& robot);

}  // namespace fleetmap
