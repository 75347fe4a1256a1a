// GET /api/maps/{map}/topology: the map's topological graph (topology_json.h).
#include "protocol/topo_store.h"
#include "server/web/api/route_groups.h"
#include "server/web/api/topology_json.h"

namespace fleetmap::web {

std::vector<Route> topology_routes() {
  return {
      {"GET", "/api/maps/{map}/topology", false, "a map's topological graph: nodes (with their type) and typed edges",
       [](const ApiRequest& req, ApiContext& ctx) {
         ApiResponse r;
         // MapNotFound, TopoGraphNotFound (a map without a graph): 404
         r.body = topology_json(TopoStore(ctx.reader()).load(req.args.at(0)));
         return r;
       }},
  };
}

}  // namespace fleetmap::web
