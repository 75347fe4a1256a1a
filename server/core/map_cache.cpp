#include "server/core/map_cache.h"

namespace fleetmap {

std::shared_ptr<const Map> MapCache::get(MapStore& store, const MapInfo& info) {
  {
    std::lock_guard lock(mutex_);
    if (auto it = maps_.find(info.id); it != maps_.end() && it->second.revision >= info.revision) return it->second.map;
  }
  MapInfo read;  // what load read: info's revision or, after a replace since, a later one
  auto m = std::make_shared<const Map>(store.load(info.name, &read));  // outside the lock: loading is slow
  if (read.id != info.id) return m;  // the name is another map's by now: nothing to keep under info.id
  std::lock_guard lock(mutex_);
  Entry& e = maps_[info.id];
  if (!e.map || e.revision < read.revision) e = {read.revision, m};
  return e.map;
}

}  // namespace fleetmap
