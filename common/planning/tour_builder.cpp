#include "common/planning/tour_builder.h"

#include <cmath>
#include <limits>
#include <set>
#include <utility>

#include "common/raycast/sweep_ray_caster.h"

namespace fleetmap {
namespace {

Placement place(const RayCaster& caster, const TourEvent& e, const TourBuildOptions& b) {
  const TourPlacementOptions& o = b.placement;
  if (b.measure) switch (e.kind) {
    case TourEventKind::EnterCorridor: return centre_in_corridor(caster, e.pose, o);
    case TourEventKind::Door: return centre_in_doorway(caster, e.pose, o);
    case TourEventKind::Crossing: return centre_in_crossing(caster, e.pose, o);
    case TourEventKind::EnterRoom:
    case TourEventKind::Place: break;
  }
  return {{e.pose.x, e.pose.y}, false, 0};
}

// The node an event at pos re-uses, or -1.
int merge_target(const std::vector<TopoNode>& nodes, const std::vector<TourEventKind>& kinds, const TourEvent& e,
                 Point pos, double merge_distance) {
  if (e.kind == TourEventKind::Place && !e.name.empty()) {
    for (size_t i = 0; i < nodes.size(); ++i)
      if (kinds[i] == TourEventKind::Place && nodes[i].name == e.name) return nodes[i].id;
  }
  int best = -1;
  double best_d = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < nodes.size(); ++i) {
    if (kinds[i] != e.kind) continue;
    // Two different names are two places, however close.
    if (e.kind == TourEventKind::Place && !e.name.empty() && !nodes[i].name.empty()) continue;
    const double d = distance(nodes[i].pos, pos);
    if (d <= merge_distance && d < best_d) best = nodes[i].id, best_d = d;
  }
  return best;
}

}  // namespace

TourGraph build_tour_graph(const RayCaster& caster, const std::vector<TourEvent>& events, const TourBuildOptions& o) {
  TourGraph t;
  // Names a merged node gets later cannot be set on TopoGraph nodes in place: nodes are
  // collected first, the graph built at the end.
  std::vector<TopoNode> nodes;
  std::vector<TopoEdge> edges;
  std::set<std::pair<int, int>> joined;
  EdgeType current = o.first_edge;
  int previous = -1;
  for (size_t k = 0; k < events.size(); ++k) {
    const TourEvent& e = events[k];
    if (!std::isfinite(e.pose.x) || !std::isfinite(e.pose.y) || !std::isfinite(e.pose.theta))
      throw TopoGraphError("tour event " + std::to_string(k) + ": expected a finite pose");
    const Placement at = place(caster, e, o);
    int id = merge_target(nodes, t.kinds, e, at.pos, o.merge_distance);
    if (id < 0) {
      id = static_cast<int>(nodes.size());
      nodes.push_back({id, at.pos, e.name});
      t.kinds.push_back(e.kind);
      t.measured.push_back(at.measured);
    } else if (nodes[static_cast<size_t>(id)].name.empty() && !e.name.empty()) {
      nodes[static_cast<size_t>(id)].name = e.name;
    }
    t.event_nodes.push_back(id);
    if (previous >= 0 && previous != id && joined.insert(std::minmax(previous, id)).second) {
      TopoEdge edge;
      edge.a = previous;
      edge.b = id;
      edge.type = current;
      edges.push_back(edge);
    }
    if (auto next = next_edge_type(e.kind)) current = *next;
    previous = id;
  }
  for (TopoNode& n : nodes) t.graph.add_node(std::move(n));
  for (const TopoEdge& e : edges) t.graph.add_edge(e);
  return t;
}

TourGraph build_tour_graph(const Map& map, const std::vector<TourEvent>& events, const TourBuildOptions& o) {
  const auto caster = make_fast_ray_caster(map, {.laser_height = 0.3, .rmax = o.placement.max_width});
  return build_tour_graph(*caster, events, o);
}

}  // namespace fleetmap
