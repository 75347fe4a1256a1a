#include "server/planner_cache.h"

namespace fleetmap {

std::shared_ptr<const MapPlanner> PlannerCache::get(MapCache& maps, MapStore& store, unsigned map_id,
                                                    const std::string& name, double radius) {
  const auto key = std::make_pair(map_id, radius);
  {
    std::lock_guard lock(mutex_);
    if (auto it = planners_.find(key); it != planners_.end()) return it->second;
  }
  PlannerOptions o;
  o.radius = radius;
  o.rrt.max_time = 1.0;  // a robot waits for the answer; better no_path than a stall
  auto p = std::make_shared<const MapPlanner>(*maps.get(store, map_id, name), o);
  std::lock_guard lock(mutex_);
  return planners_.emplace(key, p).first->second;
}

}  // namespace fleetmap
