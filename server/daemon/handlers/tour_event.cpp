// TourEvent (docs/protocol.md, an extension to SPEC 5; seed 003 §III): the guide of a
// tour told the robot about a node (a corridor or room entered, a door, a crossing, a
// named place). Recorded with the robot's pose: the one in the params, else its last
// SendPos (the robot's row, updated by SendPos requests served before in this batch).
// 'fleetmap topo tour build' turns a tour into the map's topological graph.
#include "server/daemon/handlers/handler.h"

namespace fleetmap {

void handle_tour_event(HandlerContext& ctx) {
  const TourEventParams p = decode_tour_event(ctx.params);
  TourEvent e;
  e.kind = p.kind;
  e.name = p.name;
  if (p.x) {
    e.pose = {*p.x, *p.y, *p.theta};
  } else {
    if (!ctx.robot.x || !ctx.robot.y || !ctx.robot.theta)
      throw ProtocolError(ErrorCode::NoPose, "no pose: send SendPos first, or give x, y and theta in the params");
    e.pose = {*ctx.robot.x, *ctx.robot.y, *ctx.robot.theta};
  }
  ctx.records.record_tour_event(ctx.robot.id, ctx.robot.map_id, p.tour, e, ctx.request.created_at);
  ctx.op_ack();
}

}  // namespace fleetmap
