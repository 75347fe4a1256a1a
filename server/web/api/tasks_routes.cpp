// Tasks (SPEC 5.3): GET /api/tasks, and the operator's writes on a robot: a goal, an
// initial pose, an abort. Each write calls what the CLI calls for it, on the signed-in
// person's own connection (ctx.writer(): the database's grants decide, SPEC 4):
//   goal {"x","y"}   accept_goal (server/core/goal_check.h), as `fleetmap goal R X Y`
//   goal {"tag"}     accept_goal_by_tag (server/core/goal_by_tag.h), as `--near TAG`
//   goal {"node"}    accept_goal_by_node (server/core/goal_by_node.h), as `--node WHAT`
//   pose             FleetStore::set_initial_pose, as `fleetmap pose-ini`
//   abort            FleetStore::request_abort, as `fleetmap abort`
// A refused goal is 422 goal_refused with accept_goal's message, and no task row exists.
#include "protocol/fleet_store.h"
#include "server/core/goal_by_node.h"
#include "server/core/goal_by_tag.h"
#include "server/core/goal_check.h"
#include "server/web/api/fleet_json.h"
#include "server/web/api/request_fields.h"
#include "server/web/api/route_groups.h"

namespace fleetmap::web {
namespace {

nlohmann::json xy(Point p) { return {p.x, p.y}; }

ApiResponse list_tasks(const ApiRequest& req, ApiContext& ctx) {
  const std::optional<std::string> robot = query_value(req, "robot");
  const long long limit = query_integer(req, "limit", 50, 1, 1000);
  if (robot) FleetStore(ctx.reader()).robot_id(*robot);  // RobotNotFound: 404, not an empty list
  ApiResponse r;
  r.body = read_tasks(ctx.reader(), robot, static_cast<size_t>(limit));
  return r;
}

ApiResponse created(unsigned long long task, const std::string& robot, Point goal, std::optional<Point> from,
                    double path_length) {
  ApiResponse r;
  r.status = 201;
  r.body = {{"task", task},
            {"robot", robot},
            {"goal", xy(goal)},
            {"from", from ? xy(*from) : nlohmann::json()},
            {"path_length", from ? nlohmann::json(path_length) : nlohmann::json()}};
  return r;
}

// {"node": what}: accept_goal_by_node (server/core/goal_by_node.h, as `fleetmap goal
// --node`): the node is found on the web account's reads (the robot's map, its graph),
// the goal is given on the person's own connection. No such node is a 404 here (a name
// that does not resolve, like an unknown tag), where the CLI exits 3.
ApiResponse goal_at_node(const std::string& robot, const std::string& what, ApiContext& ctx) {
  AcceptedGoalByNode g;
  try {
    g = accept_goal_by_node(ctx.reader(), ctx.writer(), robot, what, ctx.planning_defaults());
  } catch (const NoGoalNode& e) {
    throw NotFound(e.what());
  }
  ApiResponse r = created(g.goal.task, robot, g.node.pos, g.goal.check.from, g.goal.check.path_length);
  r.body["node"] = g.node.id;
  return r;
}

ApiResponse give_goal(const ApiRequest& req, ApiContext& ctx) {
  const std::string& robot = req.args.at(0);
  const nlohmann::json& body = body_object(req, {"x", "y", "tag", "node", "margin"});
  const bool by_point = has_field(body, "x") || has_field(body, "y");
  const bool by_tag = has_field(body, "tag"), by_node = has_field(body, "node");
  if (int(by_point) + int(by_tag) + int(by_node) != 1)
    throw bad_field("body", "expected exactly one of {\"x\", \"y\"}, {\"tag\"} or {\"node\"}");
  if (has_field(body, "margin") && !by_tag) throw bad_field("margin", "expected only with tag");
  if (by_tag) {
    const std::string tag = text_field(body, "tag");
    const double margin = optional_number(body, "margin").value_or(0.1);
    if (!(margin >= 0.001 && margin <= 100)) throw bad_field("margin", "expected metres in [0.001, 100]");
    const AcceptedGoalByTag g = accept_goal_by_tag(ctx.writer(), robot, tag, margin, ctx.planning_defaults());
    ApiResponse r = created(g.task, robot, g.goal, g.from, g.path_length);
    r.body["object"] = g.object;
    return r;
  }
  if (by_node) return goal_at_node(robot, text_field(body, "node"), ctx);
  const Point goal{finite_number(body, "x"), finite_number(body, "y")};
  const AcceptedGoal g = accept_goal(ctx.writer(), robot, goal, ctx.planning_defaults());  // GoalRefused: 422
  return created(g.task, robot, goal, g.check.from, g.check.path_length);
}

ApiResponse set_pose(const ApiRequest& req, ApiContext& ctx) {
  const std::string& robot = req.args.at(0);
  const nlohmann::json& body = body_object(req, {"x", "y", "theta"});
  const double x = finite_number(body, "x"), y = finite_number(body, "y");
  const std::optional<double> theta = optional_number(body, "theta");
  FleetStore(ctx.writer()).set_initial_pose(robot, x, y, theta);  // RobotNotFound: 404
  ApiResponse r;
  r.body = {{"robot", robot}, {"pose", {x, y, theta ? nlohmann::json(*theta) : nlohmann::json()}}};
  return r;
}

ApiResponse request_abort(const ApiRequest& req, ApiContext& ctx) {
  const std::string& robot = req.args.at(0);
  const nlohmann::json& body = body_object(req, {"reason"});
  const std::string reason = has_field(body, "reason") ? text_field(body, "reason") : "aborted by operator";
  if (!FleetStore(ctx.writer()).request_abort(robot, reason))  // RobotNotFound: 404
    throw ApiError(404, "not_found", "robot '" + robot + "' has no open task", 4);
  // The open task is the robot's latest (a new goal replaces the open one).
  nlohmann::json task;
  for (const RobotStatus& s : FleetStore(ctx.reader()).status())
    if (s.name == robot && s.task_id) task = *s.task_id;
  ApiResponse r;
  r.status = 202;  // the server pushes Abort; the task is aborted when the robot acknowledges
  r.body = {{"robot", robot}, {"task", task}};
  return r;
}

}  // namespace

std::vector<Route> tasks_routes() {
  return {
      {"GET", "/api/tasks", false, "tasks, newest first (?robot=R, ?limit=N, default 50)", list_tasks},
      {"POST", "/api/robots/{name}/goal", true,
       "assign a goal {x, y}, {tag} or {node}; refused at once (422) when the robot cannot reach it", give_goal},
      {"POST", "/api/robots/{name}/pose", true, "set the initial pose {x, y, theta?} the robot gets with GetPosIni",
       set_pose},
      {"POST", "/api/robots/{name}/abort", true, "abort the robot's open task {reason?}: the server pushes Abort",
       request_abort},
  };
}

}  // namespace fleetmap::web
