// GET /api/robots/{name}/trajectory?since=10m: a robot's reported poses as GeoJSON points
// with t (ISO 8601 UTC), theta and v, as `fleetmap trajectory --format geojson` writes
// them (common/io/trajectory_geojson.h), in its map's frame or (?crs=wgs84) WGS 84.
#include <regex>

#include "protocol/fleet_store.h"
#include "protocol/map_store.h"
#include "server/core/robot_tracks.h"
#include "server/web/api/map_frame.h"
#include "server/web/api/request_fields.h"
#include "server/web/api/route_groups.h"

namespace fleetmap::web {
namespace {

// What `fleetmap trajectory --since` accepts: a timestamp in the database session's time
// zone, or an age.
std::optional<std::string> since_of(const ApiRequest& req) {
  std::optional<std::string> since = query_value(req, "since");
  static const std::regex kForm(R"(^(\d{1,9}[smhd]|\d{4}-\d{2}-\d{2}( \d{2}:\d{2}(:\d{2}(\.\d{1,6})?)?)?)$)");
  if (since && !std::regex_match(*since, kForm))
    throw bad_field("since", "expected a timestamp or an age like 10m, got '" + *since + "'");
  return since;
}

ApiResponse trajectory(const ApiRequest& req, ApiContext& ctx) {
  const std::string& robot = req.args.at(0);
  const std::optional<std::string> since = since_of(req);
  FleetStore fleet(ctx.reader());
  std::string map;  // the frame is the robot's map's: its georeference gives WGS 84
  bool known = false;
  for (const RobotStatus& r : fleet.status())
    if (r.name == robot) {
      map = r.map;
      known = true;
    }
  if (!known) throw RobotNotFound(robot);
  std::optional<MapGeoref> georef;
  if (!map.empty()) georef = MapStore(ctx.reader()).info(map).georef;
  const OutputFrame frame = requested_frame(req, map, georef);
  return geojson_response(write_trajectory_geojson({load_track(fleet, robot, since)}, map, frame));
}

}  // namespace

std::vector<Route> trajectory_routes() {
  return {
      {"GET", "/api/robots/{name}/trajectory", false,
       "a robot's reported poses as GeoJSON points with t, theta, v (?since=10m; ?crs=wgs84)", trajectory},
  };
}

}  // namespace fleetmap::web
