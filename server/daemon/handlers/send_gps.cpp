// SendGPS (SPEC 5.2): the fix is stored, with map coordinates when the map is
// georeferenced.
#include "common/map/georef.h"
#include "server/daemon/handlers/handler.h"

namespace fleetmap {

void handle_send_gps(HandlerContext& ctx) {
  const SendGpsParams p = decode_send_gps(ctx.params);
  std::optional<Point> xy;
  if (const auto info = ctx.map_info(); info && info->geo_lat && info->geo_lon)
    xy = to_map({*info->geo_lat, *info->geo_lon, info->geo_heading.value_or(0)}, p.lat, p.lon);
  ctx.writes.fixes.push_back({ctx.robot.id, p, xy, ctx.request.created_at});
  ctx.op_ack();
}

}  // namespace fleetmap
