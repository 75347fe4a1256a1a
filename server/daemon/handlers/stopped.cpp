// Stopped (SPEC 5.2, 5.3): the robot stands still; an active task whose goal it reached
// is done.
#include <cmath>

#include "server/daemon/handlers/handler.h"

namespace fleetmap {

void handle_stopped(HandlerContext& ctx) {
  decode_empty(ctx.params);
  ctx.robot.state = "stopped";
  ctx.robot.v = 0;
  if (const auto& task = ctx.open_task(); task && task->state == "active" && ctx.robot.x && ctx.robot.y) {
    if (std::hypot(*ctx.robot.x - task->goal_x, *ctx.robot.y - task->goal_y) <= ctx.config.goal_tolerance_m)
      ctx.set_task_state(task->id, "done");
  }
  ctx.op_ack();
}

}  // namespace fleetmap
