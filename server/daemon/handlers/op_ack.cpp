// OpAck (SPEC 5.2, 5.3): the robot took a pushed operation: SetPosEnd -> task
// acknowledged, Abort -> task aborted (protocol/task_lifecycle.h; a late or repeated
// OpAck leaves the task as it is). Anything else is unknown_answer.
#include "server/daemon/handlers/handler.h"

namespace fleetmap {

void handle_op_ack(HandlerContext& ctx) {
  const OpAckParams p = decode_op_ack(ctx.params);
  const std::optional<TaskRow> task = ctx.records.task_pushed_as(ctx.robot.id, p.answer_id);
  if (!task)
    throw ProtocolError(ErrorCode::UnknownAnswer,
                        "answer " + std::to_string(p.answer_id) + " is not one of this robot's pushed operations");
  ctx.task_event(*task, task->abort_answer_id == p.answer_id ? TaskEvent::AbortAcknowledged
                                                               : TaskEvent::GoalAcknowledged);
}

}  // namespace fleetmap
