// SendPos (SPEC 5.2): the trajectory grows, the status shows the pose; a robot that
// moves with an acknowledged task is working on it. "status": "lost" says the robot's
// localization lost its pose (docs/protocol.md).
#include "server/daemon/handlers/handler.h"

namespace fleetmap {

void handle_send_pos(HandlerContext& ctx) {
  const SendPosParams p = decode_send_pos(ctx.params);
  if (p.lost) {
    // The robot's localization is lost (docs/protocol.md): it has stopped to localize
    // again. Its task cannot be driven on from a pose nobody knows, so it fails, as for a
    // silent robot (SPEC 5.3); the last known pose stays, the trajectory gets nothing.
    ctx.robot.state = RobotState::Localizing;
    ctx.robot.v = 0;
    if (const std::optional<TaskRow> task = ctx.open_task())
      ctx.task_event(*task, TaskEvent::RobotLost, "robot lost: its localization reported it does not know its pose");
    return;
  }
  ctx.writes.poses.push_back({ctx.robot.id, p, ctx.request.created_at});
  ctx.robot.x = p.x;
  ctx.robot.y = p.y;
  ctx.robot.theta = p.theta;
  ctx.robot.v = p.v;
  if (p.v != 0) ctx.robot.state = RobotState::Moving;
  else if (ctx.robot.state == RobotState::Moving || ctx.robot.state == RobotState::Localizing)
    ctx.robot.state = RobotState::Ready;
  if (p.v != 0)
    if (const std::optional<TaskRow> task = ctx.open_task()) ctx.task_event(*task, TaskEvent::RobotMoving);
}

}  // namespace fleetmap
