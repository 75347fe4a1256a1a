#include "server/cli/goal_near_command.h"

#include <algorithm>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/planning/goal_near.h"
#include "common/planning/planning_scene.h"
#include "protocol/fleet_store.h"
#include "protocol/live_scene.h"
#include "protocol/map_store.h"
#include "protocol/robot_whereabouts.h"
#include "protocol/scene_store.h"
#include "app/exit_codes.h"
#include "common/core/error.h"
#include "server/core/goal_check.h"
#include "server/core/planner_cache.h"

namespace fleetmap {
namespace {

int fail(int code, const std::string& message) {
  std::fprintf(stderr, "fleetmap goal: %s\n", message.c_str());
  return code;
}

std::string point(Point p) {
  char b[64];
  std::snprintf(b, sizeof b, "(%.3f, %.3f)", p.x, p.y);
  return b;
}

}  // namespace

void add_goal_near_options(CLI::App& cmd, GoalNearArgs& args) {
  cmd.add_option("--near", args.tag, "go beside the nearest object with this tag (instead of X Y)");
  cmd.add_option("--map", args.map, "with --near: the map to look in (default and only choice: the robot's)");
  cmd.add_option("--margin", args.margin, "with --near: metres kept between the robot's disc and the object")
      ->check(CLI::Range(0.001, 100.0))
      ->capture_default_str();
}

int assign_goal_near(CliContext& ctx, const std::string& robot, const GoalNearArgs& args) {
  mysqlpp::Connection& c = ctx.connection();
  const RobotWhereabouts w = robot_whereabouts(c, robot);  // RobotNotFound: exit 4
  refuse_if_lost(w, robot, "a goal beside " + args.tag);   // GoalRefused: exit 3
  if (!args.map.empty() && args.map != w.map)
    throw BadInput("--map: robot '" + robot + "' works on map '" + w.map + "', not '" + args.map +
                                "'; its goals are in its own map's frame");
  if (!w.map_id) return fail(exit_code::kNotFound, "robot '" + robot + "' has no map");
  const std::optional<Point> from = w.known_position();
  if (!from)
    return fail(exit_code::kNotFound, "robot '" + robot +
                                          "' has no known position: it has sent no pose and has no initial pose "
                                          "(fleetmap pose-ini)");
  SceneStore scenes(c);
  const std::vector<ObjectRow> nearest = scenes.near(*w.map_id, *from, args.tag, 1);
  if (nearest.empty()) return fail(exit_code::kNotFound, "no object tagged '" + args.tag + "' on map '" + w.map + "'");
  const ObjectRow& object = nearest[0];

  // The planner GetPath uses for this robot: the live scene, its profile, the server's
  // options (server/core/planner_cache.h).
  const Scene scene = load_live_scene(c, *w.map_id);
  std::vector<Polygon> footprints;
  for (const EnvObject& o : scene.objects)
    if (o.id == object.key)
      for (const Element& e : o.elements) footprints.push_back(e.footprint);
  if (footprints.empty()) return fail(exit_code::kNotFound, "object '" + object.key + "' is gone (it expired)");
  const PlannerProfile profile = planner_profile(w, planning_defaults(ctx.config_path()));
  const PlannerOptions options = server_planner_options(profile);
  const Map map = MapStore(c).load(w.map);
  const MapPlanner planner(map, planning_obstacles(map, scene, profile.body_height, options.robot), options);
  GoalNearOptions go;
  go.margin = args.margin;
  const GoalNear g = choose_goal_beside(planner, footprints, *from, go);

  const std::string what = args.tag + " '" + object.key + "'";
  switch (g.status) {
    case GoalNearStatus::Found:
      break;
    case GoalNearStatus::StartBlocked: {
      std::string why = "an obstacle";
      if (g.plan.collision)
        if (auto it = planner.checker().obstacles().names.find(g.plan.collision->obstacle_id);
            it != planner.checker().obstacles().names.end())
          why = it->second;
      return fail(exit_code::kNoPath, "robot '" + robot + "' at " + point(*from) + " is blocked by " + why +
                                          " for its radius " + std::to_string(profile.radius) + " m; no path from there");
    }
    case GoalNearStatus::NoFreeSpot:
      return fail(exit_code::kNoPath, "no free point beside " + what + ": none of " + std::to_string(g.candidates) +
                                          " points at radius + margin from it is clear for robot '" + robot + "'");
    case GoalNearStatus::NoPath:
      return fail(exit_code::kNoPath, "no path from " + point(*from) + " to any of the " + std::to_string(g.free) +
                                          " free points beside " + what + " (" + std::to_string(g.planned) +
                                          " planned)");
  }
  double gap = 1e300;  // from the goal to the object
  for (const Polygon& f : footprints) gap = std::min(gap, distance_to_polygon(g.goal, f));
  const auto task = FleetStore(c).assign_goal(robot, g.goal.x, g.goal.y);
  std::printf("task %llu assigned to '%s': goal (%.3f, %.3f) beside %s, %.3f m from it; path %.2f m from %s\n", task,
              robot.c_str(), g.goal.x, g.goal.y, what.c_str(), gap, g.plan.length, point(*from).c_str());
  return exit_code::kOk;
}

}  // namespace fleetmap
