#include "server/core/planner_cache.h"

#include "common/planning/planning_scene.h"

namespace fleetmap {

std::shared_ptr<const MapPlanner> PlannerCache::get(MapCache& maps, MapStore& store, const MapInfo& info,
                                                    const PlannerProfile& profile,
                                                    const std::shared_ptr<const Scene>& scene) {
  const Key key{info.id, profile.radius, profile.body_height, profile.can_climb_stairs};
  {
    std::lock_guard lock(mutex_);
    if (auto it = planners_.find(key);
        it != planners_.end() && it->second.revision == info.revision && it->second.scene == scene)
      return it->second.planner;
  }
  // Built outside the lock: another worker may build the same one meanwhile; the last
  // one stored wins, and both are correct.
  static const Scene kNone;
  const Scene& s = scene ? *scene : kNone;
  const PlannerOptions o = server_planner_options(profile);
  const std::shared_ptr<const Map> map = maps.get(store, info);
  auto planner = std::make_shared<const MapPlanner>(*map, planning_obstacles(*map, s, profile.body_height, o.robot), o);
  std::lock_guard lock(mutex_);
  planners_[key] = Entry{info.revision, scene, planner};
  return planner;
}

}  // namespace fleetmap
