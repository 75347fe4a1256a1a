#include "common/planning/planning_scene.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "common/geometry/polygon.h"

namespace fleetmap {
namespace {

void add_area(PlanningObstacles& out, const Polygon& ring, int id, std::string name) {
  if (const auto problem = polygon_problem(ring)) throw std::invalid_argument(name + ": " + *problem);
  add_blocked_area(out, ring, id);
  out.names.emplace(id, std::move(name));
}

}  // namespace

PlanningObstacles planning_obstacles(const Map& map, const Scene& scene, double body_height, const RobotKind& robot) {
  if (!(std::isfinite(body_height) && body_height >= 0))
    throw std::invalid_argument("expected a finite body height >= 0, got " + std::to_string(body_height));
  PlanningObstacles out = prepare_planning_obstacles(map, robot);
  // New ids after the map's largest, as common/slicing/scene_laser.h numbers them.
  int next_id = 1;
  for (const Obstacle& o : map.obstacles) next_id = std::max(next_id, o.id + 1);
  for (const EnvObject& object : scene.objects)
    for (const Element& e : object.elements)
      if (e.blocks_body(body_height)) add_area(out, e.footprint, next_id++, "object:" + object.tag + ":" + object.id);
  for (const AvoidedArea& a : scene.avoided) add_area(out, a.area, next_id++, "avoid:" + a.id);
  return out;
}

}  // namespace fleetmap
