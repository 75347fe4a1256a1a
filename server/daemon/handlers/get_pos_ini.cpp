// GetPosIni (SPEC 5.2): the initial pose an operator set (fleetmap pose-ini).
#include "server/daemon/handlers/handler.h"

namespace fleetmap {

void handle_get_pos_ini(HandlerContext& ctx) {
  decode_empty(ctx.params);
  if (!ctx.robot.ini_x || !ctx.robot.ini_y)
    throw ProtocolError(ErrorCode::NoPose, "no initial pose is set for this robot");
  ctx.answer(AnswerOp::SetPosIni, encode(SetPoseParams{*ctx.robot.ini_x, *ctx.robot.ini_y, ctx.robot.ini_theta}));
}

}  // namespace fleetmap
