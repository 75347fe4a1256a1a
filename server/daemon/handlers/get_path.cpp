// GetPath (SPEC 5.2, 7, issue 8): a path from the robot's last reported pose to the goal
// of its open task, planned on the whole map for the robot's profile (radius, body
// height, stairs; the server's defaults where the profile has none), keeping clear of
// the objects its body cannot pass and of every avoided area (common/planning/planning_scene.h);
// RRT-Connect + smoothing. The task becomes active.
#include <stdexcept>

#include "server/daemon/handlers/handler.h"
#include "server/daemon/robot_map_source.h"

namespace fleetmap {

void handle_get_path(HandlerContext& ctx) {
  decode_empty(ctx.params);
  const std::optional<TaskRow> task = ctx.open_task();
  if (!task) throw ProtocolError(ErrorCode::NoGoal, "this robot has no open task");
  if (!ctx.robot.x || !ctx.robot.y) throw ProtocolError(ErrorCode::NoPose, "send SendPos first: no pose is known");
  if (!ctx.robot.map_id) throw ProtocolError(ErrorCode::Internal, "no map is assigned to this robot");
  const std::optional<MapInfo> info = ctx.map_info();
  if (!info) throw ProtocolError(ErrorCode::Internal, "the robot's map was deleted; ask an operator");
  const PlannerProfile profile{ctx.robot.radius.value_or(ctx.config.robot_radius_m),
                               ctx.robot.body_height.value_or(ctx.config.body_height_m), ctx.robot.can_stairs};
  std::shared_ptr<const MapPlanner> planner;
  try {
    const auto scene = RobotMapSource::shared().scene(ctx.maps.connection(), info->id);
    planner = ctx.planners.get(ctx.map_cache, ctx.maps, info->id, info->name, profile, scene);
  } catch (const std::invalid_argument& e) {  // a footprint the planner cannot take
    throw ProtocolError(ErrorCode::NoPlanner, std::string("cannot plan on this map: ") + e.what());
  }
  const PlanResult r = planner->plan({*ctx.robot.x, *ctx.robot.y}, {task->goal_x, task->goal_y});
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
    throw ProtocolError(ErrorCode::NoPath, "no path to (" + std::to_string(task->goal_x) + ", " +
                                               std::to_string(task->goal_y) + "): " + why);
  }
  ctx.answer(AnswerOp::SetPath, encode(SetPathParams{*r.path, r.length}));
  if (task->state == "acknowledged" || task->state == "assigned") ctx.set_task_state(task->id, "active");
}

}  // namespace fleetmap
