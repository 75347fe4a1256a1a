#include "common/planning/topo_graph.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <queue>

namespace fleetmap {

std::string_view to_string(EdgeType t) {
  switch (t) {
    case EdgeType::Corridor: return "corridor";
    case EdgeType::Room: return "room";
    case EdgeType::Door: return "door";
    case EdgeType::Stairs: return "stairs";
    case EdgeType::Elevator: return "elevator";
  }
  return "?";
}

std::optional<EdgeType> edge_type_from_string(std::string_view s) {
  for (EdgeType t : {EdgeType::Corridor, EdgeType::Room, EdgeType::Door, EdgeType::Stairs, EdgeType::Elevator})
    if (to_string(t) == s) return t;
  return std::nullopt;
}

EdgeType edge_type_from_flags(bool door, bool automated_door, bool stairs, bool elevator) {
  // Stairs first: a wheeled robot must refuse them whatever else the edge has.
  if (stairs) return EdgeType::Stairs;
  if (elevator) return EdgeType::Elevator;
  if (door || automated_door) return EdgeType::Door;
  return EdgeType::Corridor;
}

void TopoGraph::add_node(TopoNode n) {
  if (n.id < 0) throw TopoGraphError("node id " + std::to_string(n.id) + ": expected an id >= 0");
  if (!std::isfinite(n.pos.x) || !std::isfinite(n.pos.y))
    throw TopoGraphError("node " + std::to_string(n.id) + ": expected a finite position");
  if (!index_.emplace(n.id, nodes_.size()).second)
    throw TopoGraphError("node id " + std::to_string(n.id) + ": expected a unique id, it is taken");
  nodes_.push_back(std::move(n));
  adjacent_.emplace_back();
}

void TopoGraph::add_edge(TopoEdge e) {
  const std::string what = "edge " + std::to_string(e.a) + "-" + std::to_string(e.b);
  auto ia = index_.find(e.a), ib = index_.find(e.b);
  if (ia == index_.end()) throw TopoGraphError(what + ": expected the id of a node, got " + std::to_string(e.a));
  if (ib == index_.end()) throw TopoGraphError(what + ": expected the id of a node, got " + std::to_string(e.b));
  if (e.a == e.b) throw TopoGraphError(what + ": expected two different nodes");
  // A door is crossed by a door edge (seed 003 Fig. 2), or is on stairs or an elevator.
  if ((e.door || e.automated_door) && (e.type == EdgeType::Corridor || e.type == EdgeType::Room))
    throw TopoGraphError(what + ": expected type door, stairs or elevator for an edge with a door, got " +
                         std::string(to_string(e.type)));
  // Infinity means "no limit"; NaN or a negative limit means a broken file.
  if (!(e.max_clearance >= 0)) throw TopoGraphError(what + ": expected max_clearance >= 0");
  if (!(e.max_speed > 0)) throw TopoGraphError(what + ": expected max_speed > 0");
  const size_t k = edges_.size();
  lengths_.push_back(distance(nodes_[ia->second].pos, nodes_[ib->second].pos));
  adjacent_[ia->second].push_back({k, ib->second});
  adjacent_[ib->second].push_back({k, ia->second});
  edges_.push_back(std::move(e));
}

size_t TopoGraph::index_of(int id) const {
  auto it = index_.find(id);
  if (it == index_.end()) throw TopoNodeNotFound(id);
  return it->second;
}

const TopoNode& TopoGraph::node(int id) const { return nodes_[index_of(id)]; }

bool TopoGraph::usable(size_t edge, const RouteOptions& o) const {
  const TopoEdge& e = edges_.at(edge);
  if (o.avoid_stairs && e.type == EdgeType::Stairs) return false;
  return e.max_clearance >= o.radius;
}

std::optional<TopoRoute> TopoGraph::route(int from, int to, const RouteOptions& o) const {
  const size_t s = index_of(from), t = index_of(to);
  const Point goal = nodes_[t].pos;
  constexpr double kInf = std::numeric_limits<double>::infinity();
  constexpr size_t kNone = static_cast<size_t>(-1);
  std::vector<double> g(nodes_.size(), kInf);
  std::vector<size_t> via(nodes_.size(), kNone);  // edge that reached the node
  std::vector<bool> closed(nodes_.size(), false);
  using Entry = std::pair<double, size_t>;        // (g + h, node index)
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> open;
  g[s] = 0;
  open.push({distance(nodes_[s].pos, goal), s});
  TopoRoute r;
  while (!open.empty()) {
    const size_t u = open.top().second;
    open.pop();
    if (closed[u]) continue;  // a stale entry: u was settled with a smaller key
    closed[u] = true;
    ++r.expanded;
    if (u == t) break;
    for (const Adjacent& adj : adjacent_[u]) {
      if (closed[adj.to] || !usable(adj.edge, o)) continue;
      const double d = g[u] + lengths_[adj.edge];
      if (d < g[adj.to]) {
        g[adj.to] = d;
        via[adj.to] = adj.edge;
        open.push({d + distance(nodes_[adj.to].pos, goal), adj.to});
      }
    }
  }
  if (!closed[t]) return std::nullopt;

  // Walk back along the edges that reached each node.
  for (size_t v = t;;) {
    r.nodes.push_back(nodes_[v].id);
    if (v == s) break;
    const size_t e = via[v];
    r.edges.push_back(e);
    const TopoEdge& edge = edges_[e];
    v = index_.at(edge.a == nodes_[v].id ? edge.b : edge.a);
  }
  std::reverse(r.nodes.begin(), r.nodes.end());
  std::reverse(r.edges.begin(), r.edges.end());
  r.length = g[t];
  return r;
}

std::optional<int> TopoGraph::nearest_node(Point p) const {
  std::optional<int> best;
  double best_d = std::numeric_limits<double>::infinity();
  for (const TopoNode& n : nodes_) {
    const double d = distance(n.pos, p);
    if (d < best_d) {
      best_d = d;
      best = n.id;
    }
  }
  return best;
}

Path TopoGraph::path(const TopoRoute& r) const {
  Path out;
  out.reserve(r.nodes.size());
  for (int id : r.nodes) out.push_back(node(id).pos);
  return out;
}

size_t TopoGraph::components() const {
  std::vector<bool> seen(nodes_.size(), false);
  size_t count = 0;
  std::vector<size_t> stack;
  for (size_t i = 0; i < nodes_.size(); ++i) {
    if (seen[i]) continue;
    ++count;
    seen[i] = true;
    stack.push_back(i);
    while (!stack.empty()) {
      const size_t u = stack.back();
      stack.pop_back();
      for (const Adjacent& adj : adjacent_[u])
        if (!seen[adj.to]) {
          seen[adj.to] = true;
          stack.push_back(adj.to);
        }
    }
  }
  return count;
}

}  // namespace fleetmap
