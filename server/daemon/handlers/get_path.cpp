// GetPath (SPEC 5.2, 7; seed 004 for the profile): a path from the robot's last reported pose to the goal
// of its open task, planned on the whole map for the robot's profile (radius, body
// height, stairs; the server's defaults where the profile has none), keeping clear of
// the objects its body cannot pass and of every avoided area (common/planning/planning_scene.h);
// RRT-Connect + smoothing. The task becomes active (TaskEvent::PathPlanned). No path:
// the task fails with the reason (TaskEvent::NoPath), and the answer is the no_path Error,
// so that the robot stops instead of guessing a way (client/sim/sim_robot.cpp).
//
// Through the topological graph (seed 003 §II, common/planning/topo_planner.h) when the
// map has one and start and goal are at least topo_path_min_m apart: the answer then
// carries the route's nodes and edges too (docs/protocol.md, "SetPath: nodes and
// edges"), for per-edge behaviour. When the graph gives no path (no route for this
// robot, a leg RRT-Connect did not find), whole-map RRT as below.
#include <stdexcept>

#include "common/planning/topo_planner.h"
#include "server/daemon/handlers/handler.h"

namespace fleetmap {
namespace {

// The route in travel order: edges[i] goes from nodes[i] to nodes[i + 1], whatever way
// round the graph stores it.
SetPathParams with_route(const TopoGraph& g, const TopoPlanResult& r) {
  SetPathParams p{*r.path, r.length, {}, {}};
  for (int id : r.route.nodes) {
    const TopoNode& n = g.node(id);
    p.nodes.push_back({n.id, n.name, n.pos.x, n.pos.y});
  }
  for (size_t i = 0; i < r.route.edges.size(); ++i)
    p.edges.push_back({r.route.nodes[i], r.route.nodes[i + 1], std::string(to_string(g.edges()[r.route.edges[i]].type))});
  return p;
}

// The graph's path, when the distance rule asks for it and the graph gives one.
std::optional<SetPathParams> through_graph(HandlerContext& ctx, const MapInfo& info, const MapPlanner& planner,
                                           Point start, Point goal) {
  if (distance(start, goal) < ctx.config.topo_path_min_m) return std::nullopt;
  const std::shared_ptr<const TopoGraph> graph = ctx.maps.topo_graph(info);
  if (!graph || graph->empty()) return std::nullopt;
  const TopoPlanResult r = TopoPlanner(planner, *graph).plan(start, goal);
  if (!r.path) return std::nullopt;
  return with_route(*graph, r);
}

}  // namespace

void handle_get_path(HandlerContext& ctx) {
  decode_empty(ctx.params);
  const std::optional<TaskRow> task = ctx.open_task();
  if (!task) throw ProtocolError(ErrorCode::NoGoal, "this robot has no open task");
  if (!ctx.robot.x || !ctx.robot.y) throw ProtocolError(ErrorCode::NoPose, "send SendPos first: no pose is known");
  const MapInfo info = robot_map_info(ctx);
  const PlannerProfile profile{ctx.robot.radius.value_or(ctx.config.robot_radius_m),
                               ctx.robot.body_height.value_or(ctx.config.body_height_m), ctx.robot.can_stairs};
  std::shared_ptr<const MapPlanner> planner;
  try {
    planner = ctx.maps.planner(info, profile);
  } catch (const std::invalid_argument& e) {  // a footprint the planner cannot take
    throw ProtocolError(ErrorCode::NoPlanner, std::string("cannot plan on this map: ") + e.what());
  }
  const Point start{*ctx.robot.x, *ctx.robot.y}, goal{task->goal_x, task->goal_y};
  if (std::optional<SetPathParams> p = through_graph(ctx, info, *planner, start, goal)) {
    ctx.answer(AnswerOp::SetPath, encode(*p));
    ctx.task_event(*task, TaskEvent::PathPlanned);
    return;
  }
  const PlanResult r = planner->plan(start, goal);
  if (!r.path) {
    std::string why = std::string(to_string(r.status));
    const auto& names = planner->checker().obstacles().names;
    auto near = [&](const char* what) {
      std::string s = std::string(what) + " is too close to an obstacle";
      if (r.collision)
        if (auto it = names.find(r.collision->obstacle_id); it != names.end())
          s = std::string(what) + (r.collision->kind == Collision::Kind::Area ? " is inside " : " is too close to ") +
              it->second;
      return s;
    };
    if (r.status == PlanStatus::StartBlocked) why = near("the robot's pose");
    if (r.status == PlanStatus::GoalBlocked) why = near("the goal");
    const std::string message =
        "no path to (" + std::to_string(task->goal_x) + ", " + std::to_string(task->goal_y) + "): " + why;
    // Not a refusal of the request: the task's failure is written (handler.h), so the
    // Error is answered, not thrown.
    ctx.task_event(*task, TaskEvent::NoPath, message);
    ctx.answer(AnswerOp::Error, encode(ErrorParams{ctx.request.id, ErrorCode::NoPath, message}));
    return;
  }
  ctx.answer(AnswerOp::SetPath, encode(SetPathParams{*r.path, r.length, {}, {}}));  // no graph route
  ctx.task_event(*task, TaskEvent::PathPlanned);  // refused when already active
}

}  // namespace fleetmap
