#pragma once
// One MapPlanner per map (and robot radius), built once from the whole map: building the
// clearance index costs far more than a query, and a map never changes under its id
// (MapStore::import gives a replaced map a new id).
#include <map>
#include <memory>
#include <mutex>
#include <utility>

#include "common/map_planner.h"
#include "server/map_cache.h"

namespace fleetmap {

class PlannerCache {
 public:
  std::shared_ptr<const MapPlanner> get(MapCache& maps, MapStore& store, unsigned map_id, const std::string& name,
                                        double radius);

 private:
  std::mutex mutex_;
  std::map<std::pair<unsigned, double>, std::shared_ptr<const MapPlanner>> planners_;
};

}  // namespace fleetmap
