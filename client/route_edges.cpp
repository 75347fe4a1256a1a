#include "client/route_edges.h"

#include <map>

#include "common/geometry/segment_distance.h"

namespace fleetmap {

RouteEdges::RouteEdges(const SetPathParams& p) {
  std::map<int, Point> at;
  for (const PathNode& n : p.nodes) at[n.id] = {n.x, n.y};
  for (const PathEdge& e : p.edges) {
    auto a = at.find(e.from), b = at.find(e.to);
    if (a != at.end() && b != at.end()) edges_.push_back({e, a->second, b->second});
  }
}

std::optional<size_t> RouteEdges::update(Point p) {
  if (edges_.empty()) return std::nullopt;
  size_t best = current_.value_or(0);
  double best_d2 = point_segment_distance2(p, edges_[best].a, edges_[best].b);
  for (size_t i = best + 1; i < edges_.size(); ++i)
    if (const double d2 = point_segment_distance2(p, edges_[i].a, edges_[i].b); d2 < best_d2) {
      best = i;
      best_d2 = d2;
    }
  if (current_ == best) return std::nullopt;
  current_ = best;
  return best;
}

}  // namespace fleetmap
