#include "server/core/map_cache.h"

namespace fleetmap {

std::shared_ptr<const Map> MapCache::get(MapStore& store, unsigned map_id, const std::string& name) {
  {
    std::lock_guard lock(mutex_);
    if (auto it = maps_.find(map_id); it != maps_.end()) return it->second;
  }
  auto m = std::make_shared<const Map>(store.load(name));  // outside the lock: loading is slow
  std::lock_guard lock(mutex_);
  return maps_.emplace(map_id, m).first->second;
}

}  // namespace fleetmap
