// GetPath (SPEC 5.2, 7): a path from the robot's last reported pose to the goal of its
// open task, planned on the whole map with the robot's radius (RRT-Connect + smoothing);
// the task becomes active.
#include "server/handlers/handler.h"

namespace fleetmap {

void handle_get_path(HandlerContext& ctx) {
  decode_empty(ctx.params);
  const std::optional<TaskRow> task = ctx.open_task();
  if (!task) throw ProtocolError(ErrorCode::NoGoal, "this robot has no open task");
  if (!ctx.robot.x || !ctx.robot.y) throw ProtocolError(ErrorCode::NoPose, "send SendPos first: no pose is known");
  if (!ctx.robot.map_id) throw ProtocolError(ErrorCode::Internal, "no map is assigned to this robot");
  const std::optional<MapInfo> info = ctx.map_info();
  if (!info) throw ProtocolError(ErrorCode::Internal, "the robot's map was deleted; ask an operator");
  const auto planner = ctx.planners.get(ctx.map_cache, ctx.maps, info->id, info->name, ctx.config.robot_radius_m);
  const PlanResult r = planner->plan({*ctx.robot.x, *ctx.robot.y}, {task->goal_x, task->goal_y});
  if (!r.path) {
    std::string why = std::string(to_string(r.status));
    if (r.status == PlanStatus::StartBlocked) why = "the robot's pose is too close to an obstacle";
    if (r.status == PlanStatus::GoalBlocked) why = "the goal is too close to an obstacle";
    throw ProtocolError(ErrorCode::NoPath, "no path to (" + std::to_string(task->goal_x) + ", " +
                                               std::to_string(task->goal_y) + "): " + why);
  }
  ctx.answer(AnswerOp::SetPath, encode(SetPathParams{*r.path, r.length}));
  if (task->state == "acknowledged" || task->state == "assigned") ctx.set_task_state(task->id, "active");
}

}  // namespace fleetmap
