#include "server/web/api/topology_json.h"

#include <cmath>

namespace fleetmap::web {
nlohmann::json topology_json(const TopoGraph& g) {
  const std::unordered_map<int, EdgeType> types = node_types(g);
  nlohmann::json nodes = nlohmann::json::array();
  for (const TopoNode& n : g.nodes()) {
    auto t = types.find(n.id);
    nodes.push_back({{"id", n.id},
                     {"name", n.name.empty() ? nlohmann::json() : nlohmann::json(n.name)},
                     {"type", t == types.end() ? nlohmann::json() : nlohmann::json(std::string(to_string(t->second)))},
                     {"x", n.pos.x},
                     {"y", n.pos.y}});
  }
  nlohmann::json edges = nlohmann::json::array();
  for (const TopoEdge& e : g.edges()) edges.push_back({{"from", e.a}, {"to", e.b}, {"type", std::string(to_string(e.type))}});
  return {{"nodes", std::move(nodes)}, {"edges", std::move(edges)}};
}

}  // namespace fleetmap::web
