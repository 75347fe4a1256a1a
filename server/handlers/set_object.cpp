// SetObject (SPEC 5.2): an observed object joins the map, stamped with robot and time
// (view v_observed_objects).
#include "server/handlers/handler.h"

namespace fleetmap {

void handle_set_object(HandlerContext& ctx) {
  const SetObjectParams p = decode_set_object(ctx.params);
  ctx.robots.record_object(ctx.robot.id, ctx.robot.map_id, p, ctx.request.created_at);
  ctx.op_ack();
}

}  // namespace fleetmap
