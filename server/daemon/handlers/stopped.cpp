// Stopped (SPEC 5.2, 5.3): the robot stands still; an active task whose goal it reached
// is done.
#include <cmath>

#include "server/daemon/handlers/handler.h"

namespace fleetmap {

void handle_stopped(HandlerContext& ctx) {
  decode_empty(ctx.params);
  ctx.robot.state = RobotState::Stopped;
  ctx.robot.v = 0;
  if (const std::optional<TaskRow> task = ctx.open_task(); task && ctx.robot.x && ctx.robot.y) {
    if (std::hypot(*ctx.robot.x - task->goal_x, *ctx.robot.y - task->goal_y) <= ctx.config.goal_tolerance_m)
      ctx.task_event(*task, TaskEvent::GoalReached);  // refused unless active
  }
  ctx.op_ack();
}

}  // namespace fleetmap
