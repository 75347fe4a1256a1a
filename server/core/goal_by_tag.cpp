#include "server/core/goal_by_tag.h"

#include <algorithm>
#include <cstdio>
#include <vector>

#include "common/planning/goal_near.h"
#include "common/planning/planning_scene.h"
#include "protocol/fleet_store.h"
#include "protocol/live_scene.h"
#include "protocol/map_store.h"
#include "protocol/robot_whereabouts.h"
#include "protocol/scene_store.h"
#include "server/core/planner_cache.h"

namespace fleetmap {
namespace {

std::string point(Point p) {
  char b[64];
  std::snprintf(b, sizeof b, "(%.3f, %.3f)", p.x, p.y);
  return b;
}

}  // namespace

AcceptedGoalByTag accept_goal_by_tag(mysqlpp::Connection& c, const std::string& robot, const std::string& tag,
                                     double margin, const ServerConfig& defaults) {
  const RobotWhereabouts w = robot_whereabouts(c, robot);  // RobotNotFound
  refuse_if_lost(w, robot, "a goal beside " + tag);        // GoalRefused
  if (!w.map_id) throw NoGoalByTag("robot '" + robot + "' has no map");
  const std::optional<Point> from = w.known_position();
  if (!from)
    throw NoGoalByTag("robot '" + robot +
                      "' has no known position: it has sent no pose and has no initial pose (fleetmap pose-ini)");
  SceneStore scenes(c);
  const std::vector<ObjectRow> nearest = scenes.near(*w.map_id, *from, tag, 1);
  if (nearest.empty()) throw NoGoalByTag("no object tagged '" + tag + "' on map '" + w.map + "'");
  const ObjectRow& object = nearest[0];

  // The planner GetPath uses for this robot: the live scene, its profile, the server's
  // options (server/core/planner_cache.h).
  const Scene scene = load_live_scene(c, *w.map_id);
  std::vector<Polygon> footprints;
  for (const EnvObject& o : scene.objects)
    if (o.id == object.key)
      for (const Element& e : o.elements) footprints.push_back(e.footprint);
  if (footprints.empty()) throw NoGoalByTag("object '" + object.key + "' is gone (it expired)");
  const PlannerProfile profile = planner_profile(w, defaults);
  const PlannerOptions options = server_planner_options(profile);
  const Map map = MapStore(c).load(w.map);
  const MapPlanner planner(map, planning_obstacles(map, scene, profile.body_height, options.robot), options);
  GoalNearOptions go;
  go.margin = margin;
  const GoalNear g = choose_goal_beside(planner, footprints, *from, go);

  const std::string what = tag + " '" + object.key + "'";
  switch (g.status) {
    case GoalNearStatus::Found:
      break;
    case GoalNearStatus::StartBlocked: {
      std::string why = "an obstacle";
      if (g.plan.collision)
        if (auto it = planner.checker().obstacles().names.find(g.plan.collision->obstacle_id);
            it != planner.checker().obstacles().names.end())
          why = it->second;
      throw GoalByTagRefused("robot '" + robot + "' at " + point(*from) + " is blocked by " + why +
                             " for its radius " + std::to_string(profile.radius) + " m; no path from there");
    }
    case GoalNearStatus::NoFreeSpot:
      throw GoalByTagRefused("no free point beside " + what + ": none of " + std::to_string(g.candidates) +
                             " points at radius + margin from it is clear for robot '" + robot + "'");
    case GoalNearStatus::NoPath:
      throw GoalByTagRefused("no path from " + point(*from) + " to any of the " + std::to_string(g.free) +
                             " free points beside " + what + " (" + std::to_string(g.planned) + " planned)");
  }
  AcceptedGoalByTag a;
  a.goal = g.goal;
  a.from = *from;
  a.path_length = g.plan.length;
  a.tag = tag;
  a.object = object.key;
  a.gap = 1e300;
  for (const Polygon& f : footprints) a.gap = std::min(a.gap, distance_to_polygon(g.goal, f));
  a.task = FleetStore(c).assign_goal(robot, g.goal.x, g.goal.y);
  return a;
}

}  // namespace fleetmap
