// OpAck (SPEC 5.2, 5.3): the robot took a pushed operation: SetPosEnd -> task
// acknowledged, Abort -> task aborted. Anything else is unknown_answer.
#include "server/daemon/handlers/handler.h"

namespace fleetmap {

void handle_op_ack(HandlerContext& ctx) {
  const OpAckParams p = decode_op_ack(ctx.params);
  const std::optional<TaskRow> task = ctx.robots.task_pushed_as(ctx.robot.id, p.answer_id);
  if (!task)
    throw ProtocolError(ErrorCode::UnknownAnswer,
                        "answer " + std::to_string(p.answer_id) + " is not one of this robot's pushed operations");
  if (task->abort_answer_id == p.answer_id) {
    if (task->state != "aborted") ctx.set_task_state(task->id, "aborted");
  } else if (task->state == "assigned") {
    ctx.set_task_state(task->id, "acknowledged");
  }
}

}  // namespace fleetmap
