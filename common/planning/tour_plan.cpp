#include "common/planning/tour_plan.h"

#include <functional>
#include <map>
#include <set>

namespace fleetmap {

std::vector<TourWaypoint> tour_of_graph(const TopoGraph& g, int start) {
  g.node(start);  // throws for an unknown id
  std::map<int, std::vector<size_t>> incident;  // node id -> edge indices
  for (size_t i = 0; i < g.edges().size(); ++i) {
    incident[g.edges()[i].a].push_back(i);
    incident[g.edges()[i].b].push_back(i);
  }
  auto waypoint = [&](int id) {
    TourWaypoint w{g.node(id).pos, TourEventKind::EnterCorridor, "", id};
    const size_t degree = incident[id].size();
    if (degree >= 3) w.event = TourEventKind::Crossing;
    else if (degree <= 1) w.event = TourEventKind::Place;
    if (w.event == TourEventKind::Place) w.name = g.node(id).name.empty() ? "node " + std::to_string(id) : g.node(id).name;
    return w;
  };
  std::vector<TourWaypoint> tour{waypoint(start)};
  std::set<size_t> walked;
  std::set<int> seen{start};
  // Depth first over edges; every edge is walked out and back once.
  std::function<void(int)> visit = [&](int u) {
    for (size_t e : incident[u]) {
      if (!walked.insert(e).second) continue;
      const TopoEdge& edge = g.edges()[e];
      const int v = edge.a == u ? edge.b : edge.a;
      tour.push_back(waypoint(v));
      if (seen.insert(v).second) visit(v);
      tour.push_back(waypoint(u));
    }
  };
  visit(start);
  return tour;
}

std::vector<TourWaypoint> keep_right(std::vector<TourWaypoint> tour, double offset) {
  const std::vector<TourWaypoint> on_line = tour;
  for (size_t i = 0; i < tour.size(); ++i) {
    Point d{0, 0};
    for (size_t j = i; j > 0 && norm(d) < 1e-9; --j) d = on_line[j].p - on_line[j - 1].p;
    for (size_t j = i + 1; j < tour.size() && norm(d) < 1e-9; ++j) d = on_line[j].p - on_line[i].p;
    if (norm(d) < 1e-9) continue;
    const Point right{d.y / norm(d), -d.x / norm(d)};
    tour[i].p = on_line[i].p + offset * right;
  }
  return tour;
}

}  // namespace fleetmap
