// SendPos (SPEC 5.2): the trajectory grows, the status shows the pose; a robot that
// moves with an acknowledged task is working on it.
#include "server/daemon/handlers/handler.h"

namespace fleetmap {

void handle_send_pos(HandlerContext& ctx) {
  const SendPosParams p = decode_send_pos(ctx.params);
  ctx.writes.poses.push_back({ctx.robot.id, p, ctx.request.created_at});
  ctx.robot.x = p.x;
  ctx.robot.y = p.y;
  ctx.robot.theta = p.theta;
  ctx.robot.v = p.v;
  if (p.v != 0) ctx.robot.state = RobotState::Moving;
  else if (ctx.robot.state == RobotState::Moving) ctx.robot.state = RobotState::Ready;
  if (p.v != 0)
    if (const std::optional<TaskRow> task = ctx.open_task()) ctx.task_event(*task, TaskEvent::RobotMoving);
}

}  // namespace fleetmap
