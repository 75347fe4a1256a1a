// SendPos (SPEC 5.2): the trajectory grows, the status shows the pose; a robot that
// moves with an acknowledged task is working on it.
#include "server/handlers/handler.h"

namespace fleetmap {

void handle_send_pos(HandlerContext& ctx) {
  const SendPosParams p = decode_send_pos(ctx.params);
  ctx.robots.record_pose(ctx.robot.id, p, ctx.request.created_at);
  ctx.robot.x = p.x;
  ctx.robot.y = p.y;
  ctx.robot.theta = p.theta;
  if (p.v != 0)
    if (auto task = ctx.robots.open_task(ctx.robot.id); task && task->state == "acknowledged")
      ctx.robots.set_task_state(task->id, "active");
}

}  // namespace fleetmap
