#include "server/web/api/topology_json.h"

#include <cmath>

namespace fleetmap::web {
namespace {

// Higher: more telling (what a robot must know before it drives to the node).
int rank(EdgeType t) {
  switch (t) {
    case EdgeType::Stairs:
      return 5;
    case EdgeType::Elevator:
      return 4;
    case EdgeType::Door:
      return 3;
    case EdgeType::Room:
      return 2;
    case EdgeType::Corridor:
      return 1;
  }
  return 0;
}

}  // namespace

std::unordered_map<int, EdgeType> node_types(const TopoGraph& g) {
  std::unordered_map<int, EdgeType> types;
  for (const TopoEdge& e : g.edges())
    for (int n : {e.a, e.b}) {
      auto [it, added] = types.emplace(n, e.type);
      if (!added && rank(e.type) > rank(it->second)) it->second = e.type;
    }
  return types;
}

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

const TopoNode* find_goal_node(const TopoGraph& g, const std::string& what, const std::optional<Point>& near) {
  const auto nearest = [&](auto matches) -> const TopoNode* {
    const TopoNode* best = nullptr;
    double best_d = 0;
    for (const TopoNode& n : g.nodes()) {
      if (!matches(n)) continue;
      const double d = near ? std::hypot(n.pos.x - near->x, n.pos.y - near->y) : 0;
      if (!best || d < best_d) {
        best = &n;
        best_d = d;
      }
    }
    return best;
  };
  if (const TopoNode* n = nearest([&](const TopoNode& n) { return n.name == what; })) return n;
  const std::optional<EdgeType> type = edge_type_from_string(what);
  if (!type) return nullptr;
  const std::unordered_map<int, EdgeType> types = node_types(g);
  return nearest([&](const TopoNode& n) {
    auto t = types.find(n.id);
    return t != types.end() && t->second == *type;
  });
}

}  // namespace fleetmap::web
