// GetPosEnd (SPEC 5.2): the goal of the robot's open task.
#include "server/daemon/handlers/handler.h"

namespace fleetmap {

void handle_get_pos_end(HandlerContext& ctx) {
  decode_empty(ctx.params);
  const std::optional<TaskRow>& task = ctx.open_task();
  if (!task) throw ProtocolError(ErrorCode::NoGoal, "this robot has no open task");
  ctx.answer(AnswerOp::SetPosEnd, encode(SetPoseParams{task->goal_x, task->goal_y, std::nullopt}));
}

}  // namespace fleetmap
