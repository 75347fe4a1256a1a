// SetObject (SPEC 5.2): an observed object joins the map, stamped with robot and time.
// Two records: the report as it came (observed_objects, view v_observed_objects), and,
// when the robot has a map, a dynamic object of the map's semantic layer
// (SceneStore::record_observation: env_objects, view v_objects) that expires
// config.object_ttl_s after its last sighting unless seen again; the housekeeping worker
// deletes it then (server/daemon/housekeeping.h). Robots' maps show it from the next
// batch on (server/daemon/robot_map_source.h).
#include "server/daemon/handlers/handler.h"

namespace fleetmap {

void handle_set_object(HandlerContext& ctx) {
  // Everything that may refuse the request is checked here, before the first write
  // (handler.h): decode refuses a non-finite position and an empty or over-long name,
  // which is all record_observation would refuse.
  const SetObjectParams p = decode_set_object(ctx.params);
  ctx.records.record_object(ctx.robot.id, ctx.robot.map_id, p, ctx.request.created_at);
  if (ctx.robot.map_id)
    ctx.records.record_observation(*ctx.robot.map_id, ctx.robot.id, p, ctx.config.object_ttl_s, ctx.request.created_at);
  ctx.op_ack();
}

}  // namespace fleetmap
