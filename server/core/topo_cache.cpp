#include "server/core/topo_cache.h"

namespace fleetmap {

std::shared_ptr<const TopoGraph> TopoCache::get(TopoStore& store, const std::string& map) {
  TopoInfo info;
  try {
    info = store.info(map);
  } catch (const NotFound&) {  // MapNotFound, TopoGraphNotFound: plan without a graph
    std::lock_guard lock(mutex_);
    graphs_.erase(map);
    return nullptr;
  }
  const std::string stamp = info.imported_at + "/" + std::to_string(info.nodes) + "/" + std::to_string(info.edges);
  {
    std::lock_guard lock(mutex_);
    if (auto it = graphs_.find(map); it != graphs_.end() && it->second.stamp == stamp) return it->second.graph;
  }
  // Loaded outside the lock, as PlannerCache builds: two workers may both load it, and
  // either copy is right. A replace between info() and load() gives the newer graph
  // under the older stamp, which only costs one more load next time.
  auto graph = std::make_shared<const TopoGraph>(store.load(map));
  std::lock_guard lock(mutex_);
  graphs_[map] = Entry{stamp, graph};
  return graph;
}

}  // namespace fleetmap
