#pragma once
// One MapPlanner per map, robot profile and scene (seed 004): building the clearance index
// costs far more than a query, so planners are kept and shared by the workers.
//
//   key      (map id, radius, body height, climbs stairs): the profile decides what
//            blocks (common/planning/planning_scene.h). A replace keeps the map's id and
//            moves its revision (MapStore::import): a planner of an older revision is
//            rebuilt.
//   scene    the map's live scene as server/daemon/robot_map_source.h serves it: one Scene
//            object per scene version (it re-reads the version cheaply and loads a new
//            Scene only when it changed). A planner built on an older Scene object is
//            rebuilt, so an import, avoid add/remove or observation reaches GetPath as
//            it reaches the robots' maps.
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <tuple>

#include "common/planning/map_planner.h"
#include "common/scene/scene.h"
#include "server/core/map_cache.h"

namespace fleetmap {

struct PlannerProfile {
  double radius = 0.3;       // metres
  double body_height = 1.0;  // metres: elements starting below this block
  bool can_climb_stairs = false;
};

// How the server plans (GetPath) and how `fleetmap goal --near` chooses, so that the
// goal it chooses is one GetPath reaches: a robot waits for the answer, so a time limit
// (better no_path than a stall).
inline PlannerOptions server_planner_options(const PlannerProfile& profile) {
  PlannerOptions o;
  o.radius = profile.radius;
  o.robot.can_climb_stairs = profile.can_climb_stairs;
  o.rrt.max_time = 1.0;
  return o;
}

class PlannerCache {
 public:
  // The planner of the map `info` describes (id, revision) for the profile with the
  // scene's objects and avoided areas; the map is loaded through store on first use.
  // Throws std::invalid_argument for a scene the planner cannot take (a malformed footprint).
  std::shared_ptr<const MapPlanner> get(MapCache& maps, MapStore& store, const MapInfo& info,
                                        const PlannerProfile& profile, const std::shared_ptr<const Scene>& scene);

 private:
  using Key = std::tuple<unsigned, double, double, bool>;
  struct Entry {
    unsigned revision = 0;
    std::shared_ptr<const Scene> scene;
    std::shared_ptr<const MapPlanner> planner;
  };
  std::mutex mutex_;
  std::map<Key, Entry> planners_;
};

}  // namespace fleetmap
