// Alive (SPEC 5.2): liveness only; every request refreshes it (request_loop), so there is
// nothing more to do than to check its params.
#include "server/daemon/handlers/handler.h"

namespace fleetmap {

void handle_alive(HandlerContext& ctx) { decode_empty(ctx.params); }

}  // namespace fleetmap
