#include "server/web/api/api.h"
#include "server/web/api/route_groups.h"

namespace fleetmap::web {

std::vector<Route> api_routes() {
  std::vector<Route> all;
  for (auto group : {maps_routes, objects_routes, topology_routes, robots_routes, tasks_routes, trajectory_routes})
    for (Route& r : group()) all.push_back(std::move(r));
  return all;
}

}  // namespace fleetmap::web
