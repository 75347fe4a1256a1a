// SendGPS (SPEC 5.2): the fix is stored, with map coordinates when the map is
// georeferenced (through PROJ, common/gis/geo_transform.h).
#include <optional>

#include "common/core/error.h"
#include "common/gis/geo_transform.h"
#include "server/daemon/handlers/handler.h"

namespace fleetmap {

namespace {

// Building a PROJ transformation takes milliseconds; a fix takes microseconds. One
// transform per handler thread, rebuilt when the map's georeference changes.
const GeoTransform& transform_for(const MapGeoref& g) {
  thread_local std::optional<GeoTransform> cached;
  if (!cached || !(cached->georef() == g)) cached.emplace(g);
  return *cached;
}

}  // namespace

void handle_send_gps(HandlerContext& ctx) {
  const SendGpsParams p = decode_send_gps(ctx.params);
  std::optional<Point> xy;
  if (const auto info = ctx.map_info(); info && info->georef) {
    try {
      xy = transform_for(*info->georef).to_map({p.lon, p.lat});
    } catch (const BadInput&) {
      // A fix PROJ cannot place in the map's CRS is still a fix: stored without x, y.
    }
  }
  ctx.writes.fixes.push_back({ctx.robot.id, p, xy, ctx.request.created_at});
  ctx.op_ack();
}

}  // namespace fleetmap
