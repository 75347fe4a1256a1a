#include "server/core/goal_by_node.h"

#include <cmath>

#include "protocol/robot_whereabouts.h"
#include "protocol/topo_store.h"

namespace fleetmap {
namespace {

// Higher: more telling (what a robot must know before it drives to the node).
int rank(EdgeType t) {
  switch (t) {
    case EdgeType::Stairs: return 5;
    case EdgeType::Elevator: return 4;
    case EdgeType::Door: return 3;
    case EdgeType::Room: return 2;
    case EdgeType::Corridor: return 1;
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

AcceptedGoalByNode accept_goal_by_node(mysqlpp::Connection& reads, mysqlpp::Connection& writes,
                                       const std::string& robot, const std::string& what,
                                       const ServerConfig& defaults) {
  const RobotWhereabouts w = robot_whereabouts(reads, robot);  // RobotNotFound
  if (w.map.empty()) throw NotFound("robot '" + robot + "' has no map");
  const TopoGraph graph = TopoStore(reads).load(w.map);  // TopoGraphNotFound
  const TopoNode* node = find_goal_node(graph, what, w.known_position());
  if (!node)
    throw NoGoalNode("no node named '" + what + "' and none of that type in the topological graph of map '" + w.map +
                     "' (node types: corridor, room, door, stairs, elevator)");
  return {accept_goal(writes, robot, node->pos, defaults), *node};
}

}  // namespace fleetmap
