#pragma once
// The maps' topological graphs for GetPath (SPEC 7, seed 003), kept between requests: a
// graph is read whole from topo_nodes and topo_edges (protocol/topo_store.h), which
// costs far more than the one-row check that it has not changed. The check is the graph's
// topo_graphs row (import time to the microsecond, node and edge counts): an import,
// replace or removal is seen by the next GetPath.
//
//   TopoCache cache;
//   TopoStore store(conn);
//   if (std::shared_ptr<const TopoGraph> g = cache.get(store, "campus")) route_on(*g);
#include <map>
#include <memory>
#include <mutex>
#include <string>

#include "common/planning/topo_graph.h"
#include "protocol/topo_store.h"

namespace fleetmap {

class TopoCache {
 public:
  // The map's graph, or nullptr when the map has none (or no longer exists).
  std::shared_ptr<const TopoGraph> get(TopoStore& store, const std::string& map);

 private:
  struct Entry {
    std::string stamp;  // imported_at, nodes, edges
    std::shared_ptr<const TopoGraph> graph;
  };
  std::mutex mutex_;
  std::map<std::string, Entry> graphs_;
};

}  // namespace fleetmap
