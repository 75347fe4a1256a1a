#include "server/core/goal_check.h"

#include <cstdio>
#include <map>

#include "common/core/error.h"
#include "common/geometry/number_format.h"
#include "common/geometry/polygon.h"
#include "common/planning/planning_scene.h"
#include "common/planning/topo_planner.h"
#include "protocol/db_settings.h"
#include "protocol/fleet_store.h"
#include "protocol/live_scene.h"
#include "protocol/map_store.h"
#include "protocol/topo_store.h"

namespace fleetmap {
namespace {

std::string point(Point p) {
  char b[80];
  std::snprintf(b, sizeof b, "(%.3f, %.3f)", p.x, p.y);
  return b;
}

// What a blocked disc touches, in the words of `fleetmap plan`.
std::string blocker(const Collision& c, const PlanningObstacles& obstacles, double radius) {
  const auto named = obstacles.names.find(c.obstacle_id);
  const std::string r = format_number(radius) + " m";
  switch (c.kind) {
    case Collision::Kind::Border:
      return "a robot of radius " + r + " centred there does not fit inside the map's border";
    case Collision::Kind::Area:
      if (named != obstacles.names.end()) return "it is inside " + named->second;
      return "it is on the stairs of obstacle " + std::to_string(c.obstacle_id) + ", which a wheeled robot may not enter";
    case Collision::Kind::Segment:
      break;
  }
  return "it is within the robot's radius " + r + " of " +
         (named != obstacles.names.end() ? named->second : "obstacle " + std::to_string(c.obstacle_id));
}

}  // namespace

PlannerProfile planner_profile(const RobotWhereabouts& w, const ServerConfig& defaults) {
  return {w.radius.value_or(defaults.robot_radius_m), w.body_height.value_or(defaults.body_height_m), w.can_stairs};
}

ServerConfig planning_defaults(const std::optional<std::string>& config_file) {
  ServerConfig defaults;
  std::optional<std::string> file = config_file ? config_file : find_config_file();
  if (!file) return defaults;
  const std::map<std::string, std::string> server = program_settings(Role::Server, *file);
  std::map<std::string, std::string> planning;
  for (const char* key : {"robot_radius_m", "body_height_m"})
    if (auto it = server.find(key); it != server.end()) planning.emplace(key, it->second);
  defaults.apply(planning);  // std::invalid_argument for a bad value: exit 2, as the server refuses it
  return defaults;
}

void refuse_if_lost(const RobotWhereabouts& w, const std::string& robot, const std::string& goal) {
  if (w.state == RobotState::Localizing)
    throw GoalRefused(goal + " for robot '" + robot +
                      "' refused: the robot is localizing (its localization lost its pose); give the goal again once "
                      "it reports a pose (fleetmap robots)");
  if (w.state != RobotState::Lost) return;
  // Refused, not queued: its last pose is stale, and a queued goal would start the
  // robot the moment it comes back, perhaps somewhere else (SPEC 5.3).
  throw GoalRefused(goal + " for robot '" + robot + "' refused: the robot is lost (silent since " +
                    (w.last_seen.empty() ? std::string("its start") : w.last_seen) +
                    "), its position is unknown; give the goal again once it reports (fleetmap robots)");
}

const Obstacle* enclosing_obstacle(const Map& map, Point p) {
  for (const Obstacle& o : map.obstacles) {
    if (o.type != ShapeType::ClosedPolygon && o.type != ShapeType::ClosedCurved) continue;
    if (o.segments.size() < 3) continue;
    bool blocks = true;  // common/planning/planning_obstacles.h: h = 0 does not block
    Polygon ring;
    for (const Segment& s : o.segments) {
      blocks = blocks && s.h > 0;
      ring.push_back(s.a);
    }
    if (blocks && point_in_polygon(p, ring)) return &o;
  }
  return nullptr;
}

GoalAcceptance check_goal_on(const MapPlanner& planner, const Map& m, const std::string& robot,
                             const std::string& map, std::optional<Point> from, Point goal, const TopoGraph* graph) {
  const std::string refused = "goal " + point(goal) + " for robot '" + robot + "' refused: ";
  const Rect border = m.border.rect();
  if (!border.contains(goal))
    throw GoalRefused(refused + "it is outside the map '" + map + "' (border x " + format_number(border.xmin) +
                      ".." + format_number(border.xmax) + ", y " + format_number(border.ymin) + ".." +
                      format_number(border.ymax) + ")");
  const ClearanceChecker& checker = planner.checker();
  if (const std::optional<Collision> c = checker.collision(goal))
    throw GoalRefused(refused + blocker(*c, checker.obstacles(), checker.radius()));
  if (const Obstacle* o = enclosing_obstacle(m, goal); o && !(from && enclosing_obstacle(m, *from) == o))
    throw GoalRefused(refused + "it is inside obstacle " + std::to_string(o->id) +
                      (o->semantic.empty() ? "" : " (" + o->semantic + ")") +
                      ", closed on every side for a robot");
  GoalAcceptance a;
  if (!from) return a;  // no known position: GetPath plans once the robot reports one
  const PlanResult r = planner.plan(*from, goal);
  switch (r.status) {
    case PlanStatus::Found:
      a.from = from;
      a.path_length = r.length;
      return a;
    case PlanStatus::StartBlocked:
      throw GoalRefused(refused + "the robot's position " + point(*from) + " is blocked (" +
                        (r.collision ? blocker(*r.collision, checker.obstacles(), checker.radius()) : "?") +
                        "): no path from there");
    case PlanStatus::GoalBlocked:  // checked above; kept for a planner that is stricter
      throw GoalRefused(refused + "it is blocked");
    case PlanStatus::NoPath:
      // RRT-Connect gave up (its time limit on a long trip over a dense floor,
      // docs/benchmarks.md): the map's graph, as GetPath would use it, may still get there.
      if (graph && !graph->empty())
        if (const TopoPlanResult t = TopoPlanner(planner, *graph).plan(*from, goal); t.path) {
          a.from = from;
          a.path_length = t.length;
          return a;
        }
      break;
  }
  throw GoalRefused(refused + "no path from the robot's position " + point(*from) + " for its radius " +
                    format_number(checker.radius()) + " m" + (r.rrt.timed_out ? " within the planner's time limit" : "") +
                    " (unreachable for its profile)");
}

GoalAcceptance check_goal(mysqlpp::Connection& c, const std::string& robot, Point goal, const ServerConfig& defaults) {
  const RobotWhereabouts w = robot_whereabouts(c, robot);  // RobotNotFound
  refuse_if_lost(w, robot, "goal " + point(goal));
  if (!w.map_id) throw NotFound("robot '" + robot + "' has no map");
  const PlannerProfile profile = planner_profile(w, defaults);
  PlannerOptions options = server_planner_options(profile);
  options.attempts = 1;     // whether a path exists, not the shortest: the first run answers it
  options.smooth = false;
  const Map map = MapStore(c).load(w.map);
  const Scene scene = load_live_scene(c, *w.map_id);
  const MapPlanner planner(map, planning_obstacles(map, scene, profile.body_height, options.robot), options);
  std::optional<TopoGraph> graph;
  try {
    graph = TopoStore(c).load(w.map);
  } catch (const TopoGraphNotFound&) {  // no graph: whole-map RRT only
  }
  return check_goal_on(planner, map, robot, w.map, w.known_position(), goal, graph ? &*graph : nullptr);
}

AcceptedGoal accept_goal(mysqlpp::Connection& c, const std::string& robot, Point goal, const ServerConfig& defaults) {
  AcceptedGoal a;
  a.check = check_goal(c, robot, goal, defaults);
  a.task = FleetStore(c).assign_goal(robot, goal.x, goal.y);
  return a;
}

}  // namespace fleetmap
