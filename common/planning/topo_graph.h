#pragma once
// Topological map (SPEC 7, seed 003 §II-A): places as nodes with a position in the map
// frame, connected by typed edges; the shortest route between two nodes.
//
// Edge types. Seed 003 has three: corridor, room and door ("nodes have to be placed at
// every position of the environment where the edge type would change"). The AMRL
// navigation graphs (ut-amrl/amrl_maps *.navigation.json) have no types, only flags; we add
// stairs and elevator because a wheeled robot must be able to refuse them. From the
// flags, in this order: has_stairs -> stairs, has_elevator -> elevator, has_door or
// has_automated_door -> door, none -> corridor. Stairs come first because avoiding them
// is what the type is for (stairs behind a door are still stairs). "room" cannot be told
// from the flags (a room edge and a corridor edge look alike in AMRL data), so it comes
// only from an explicit "type" in the file (topo_json.h); we never guess it.
//
// Edge lengths are the Euclidean distance between the end nodes (seed 003 measured
// distances between nodes; our nodes carry positions, so the distance is that).
//
//   TopoGraph g;
//   g.add_node({0, {0, 0}});  g.add_node({1, {10, 0}});
//   g.add_edge({.a = 0, .b = 1, .type = EdgeType::Door});
//   if (auto r = g.route(0, 1, {.avoid_stairs = true, .radius = 0.3})) use(r->nodes, r->length);
#include <cstddef>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "common/geometry/geometry.h"
#include "common/core/error.h"
#include "common/planning/path.h"

namespace fleetmap {

enum class EdgeType { Corridor, Room, Door, Stairs, Elevator };

std::string_view to_string(EdgeType t);                       // "corridor", "room", ...
std::optional<EdgeType> edge_type_from_string(std::string_view s);

// The type the AMRL flags say (see the header comment): stairs, elevator, door, corridor.
EdgeType edge_type_from_flags(bool door, bool automated_door, bool stairs, bool elevator);

struct TopoNode {
  int id = 0;         // unique in the graph, >= 0
  Point pos;          // map frame, metres
  std::string name;   // optional ("" when the node has none), e.g. "charging station"
  friend bool operator==(const TopoNode&, const TopoNode&) = default;
};

struct TopoEdge {
  int a = 0, b = 0;   // node ids (AMRL s0_id, s1_id); edges are undirected
  EdgeType type = EdgeType::Corridor;
  bool door = false;            // AMRL has_door: a door the robot must have opened
  bool automated_door = false;  // AMRL has_automated_door
  // AMRL: the free half-width along the edge, and the speed limit on it. A disc robot of
  // radius r may use the edge when max_clearance >= r.
  double max_clearance = std::numeric_limits<double>::infinity();
  double max_speed = std::numeric_limits<double>::infinity();  // m/s
  friend bool operator==(const TopoEdge&, const TopoEdge&) = default;
};

// A graph that cannot be built: duplicate node id, edge to a missing node, NaN position.
class TopoGraphError : public BadInput {
 public:
  using BadInput::BadInput;
};

class TopoNodeNotFound : public NotFound {
 public:
  explicit TopoNodeNotFound(int id) : NotFound("no node with id " + std::to_string(id)), id_(id) {}
  int id() const { return id_; }

 private:
  int id_;
};

struct RouteOptions {
  bool avoid_stairs = false;  // a wheeled robot: stairs edges are not usable
  double radius = 0;          // robot radius: only edges with max_clearance >= radius
};

struct TopoRoute {
  std::vector<int> nodes;     // node ids, from the start to the goal
  std::vector<size_t> edges;  // indices into TopoGraph::edges(), edges[i] joins nodes[i], nodes[i + 1]
  double length = 0;          // metres
  size_t expanded = 0;        // nodes the search settled
};

class TopoGraph {
 public:
  // Throws TopoGraphError: id < 0 or taken, non-finite position.
  void add_node(TopoNode n);
  // Throws TopoGraphError: unknown end node, a == b, NaN clearance or speed.
  // Parallel edges are kept (the campus graph lists some pairs twice).
  void add_edge(TopoEdge e);

  const std::vector<TopoNode>& nodes() const { return nodes_; }
  const std::vector<TopoEdge>& edges() const { return edges_; }
  bool empty() const { return nodes_.empty(); }

  bool has_node(int id) const { return index_.count(id) != 0; }
  const TopoNode& node(int id) const;   // throws TopoNodeNotFound
  double length(size_t edge) const { return lengths_.at(edge); }
  bool usable(size_t edge, const RouteOptions& o) const;

  // The shortest route (A*, Euclidean heuristic: admissible since every edge is at least
  // as long as the straight line between its ends), or nullopt when no route uses only
  // usable edges. Throws TopoNodeNotFound for an unknown id.
  std::optional<TopoRoute> route(int from, int to, const RouteOptions& o = {}) const;

  // The id of the node nearest to p (ties: the first in node order); nullopt when empty.
  std::optional<int> nearest_node(Point p) const;

  // The positions of a route's nodes, as a planned path.
  Path path(const TopoRoute& r) const;

  // Connected components over all edges (for reports).
  size_t components() const;

  friend bool operator==(const TopoGraph& l, const TopoGraph& r) {
    return l.nodes_ == r.nodes_ && l.edges_ == r.edges_;
  }

 private:
  struct Adjacent {
    size_t edge;
    size_t to;  // node index
  };
  size_t index_of(int id) const;  // throws TopoNodeNotFound

  std::vector<TopoNode> nodes_;
  std::vector<TopoEdge> edges_;
  std::vector<double> lengths_;                 // per edge
  std::vector<std::vector<Adjacent>> adjacent_;  // per node
  std::unordered_map<int, size_t> index_;       // node id -> index
};

}  // namespace fleetmap
