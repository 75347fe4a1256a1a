// GetPath (SPEC 5.2): planning comes with the planning issue; until then no planner.
#include "server/handlers/handler.h"

namespace fleetmap {

void handle_get_path(HandlerContext& ctx) {
  decode_empty(ctx.params);
  throw ProtocolError(ErrorCode::NoPlanner, "this server has no path planner yet");
}

}  // namespace fleetmap
