#pragma once
// The routes of each resource (one file each, server/web/api/*_routes.cpp); api_routes()
// is their concatenation in this order.
#include <vector>

#include "server/web/api/api.h"

namespace fleetmap::web {

std::vector<Route> maps_routes();        // GET /api/maps, /api/maps/{map}
std::vector<Route> objects_routes();     // GET /api/maps/{map}/objects, /avoided
std::vector<Route> topology_routes();    // GET /api/maps/{map}/topology
std::vector<Route> robots_routes();      // GET /api/robots, /api/robots/{name}
std::vector<Route> tasks_routes();       // GET /api/tasks; POST goal, pose, abort
std::vector<Route> trajectory_routes();  // GET /api/robots/{name}/trajectory

}  // namespace fleetmap::web
