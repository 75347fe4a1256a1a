// GET /api/robots and GET /api/robots/{name}: the robots' states (fleet_json.h), one
// with its profile (seed 004 section III.A: what its maps and plans depend on).
#include "protocol/fleet_store.h"
#include "server/web/api/fleet_json.h"
#include "server/web/api/route_groups.h"

namespace fleetmap::web {
namespace {

nlohmann::json number_or_null(const std::optional<double>& v) { return v ? nlohmann::json(*v) : nlohmann::json(); }

ApiResponse list_robots(const ApiRequest&, ApiContext& ctx) {
  ApiResponse r;
  r.body = read_robot_states(ctx.reader());
  return r;
}

// null in the profile: the server's default (robot_radius_m, body_height_m; no laser
// height: maps unsliced), as `fleetmap robot list --json` says it.
ApiResponse one_robot(const ApiRequest& req, ApiContext& ctx) {
  const std::string& name = req.args.at(0);
  ApiResponse r;
  r.body = read_robot_state(ctx.reader(), name);  // RobotNotFound: 404
  const RobotProfile p = FleetStore(ctx.reader()).profile(name);
  r.body["profile"] = {{"laser_height", number_or_null(p.laser_height)},
                       {"radius", number_or_null(p.radius)},
                       {"body_height", number_or_null(p.body_height)},
                       {"can_stairs", p.can_stairs},
                       {"can_ramps", p.can_ramps}};
  return r;
}

}  // namespace

std::vector<Route> robots_routes() {
  return {
      {"GET", "/api/robots", false, "every robot's state: pose, state, task, goal, last seen", list_robots},
      {"GET", "/api/robots/{name}", false, "one robot's state and its profile", one_robot},
  };
}

}  // namespace fleetmap::web
