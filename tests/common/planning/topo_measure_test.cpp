// Measurement, not a check (SPEC 8): long trips on the campus, routed on the topological
// graph (TopoGraph::route) vs planned straight on the vector map (MapPlanner: RRT-Connect
// + smoothing, SPEC 7), from the same start node to the same goal node. Prints numbers;
// asserts nothing about time. Disabled by default (a few seconds of RRT); run with
//
//   build/bin/common_tests --gtest_filter='TopoMeasure*' --gtest_also_run_disabled_tests
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "common/io/amrl_import.h"
#include "common/planning/map_planner.h"
#include "common/planning/topo_graph.h"
#include "common/io/topo_json.h"

namespace fleetmap {
namespace {

using Clock = std::chrono::steady_clock;

double median(std::vector<double> v) {
  if (v.empty()) return NAN;
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

TEST(TopoMeasure, DISABLED_CampusGraphRouteVsRrt) {
  const std::string dir = FLEETMAP_REAL_MAPS;
  const Map map = read_amrl_file(dir + "/UT_Campus.vectormap.txt", AmrlOptions{});
  const TopoGraph g = read_topo_json_file(dir + "/UT_Campus.navigation.json");
  const double radius = 0.3, min_distance = 150;
  const RouteOptions wheeled{.avoid_stairs = true, .radius = radius};

  PlannerOptions po;
  po.radius = radius;
  const MapPlanner planner(map, po);
  const ClearanceChecker& checker = planner.checker();

  // How well the graph sits on the vector map, for a robot of this radius.
  size_t clear_nodes = 0, clear_edges = 0;
  for (const TopoNode& n : g.nodes()) clear_nodes += checker.point_clear(n.pos);
  for (const TopoEdge& e : g.edges()) clear_edges += checker.motion_clear(g.node(e.a).pos, g.node(e.b).pos);
  std::printf("campus graph on the campus map, radius %.2f m: %zu of %zu nodes clear, %zu of %zu edges clear\n",
              radius, clear_nodes, g.nodes().size(), clear_edges, g.edges().size());

  // Long trips: node pairs at least min_distance apart as the crow flies, joined without stairs.
  std::vector<std::pair<int, int>> pairs;
  for (const TopoNode& a : g.nodes())
    for (const TopoNode& b : g.nodes())
      if (a.id < b.id && distance(a.pos, b.pos) >= min_distance && g.route(a.id, b.id, wheeled)) pairs.push_back({a.id, b.id});
  std::mt19937 rng(3);
  std::shuffle(pairs.begin(), pairs.end(), rng);
  const size_t n = std::min<size_t>(pairs.size(), 30);
  pairs.resize(n);
  std::printf("%zu node pairs >= %.0f m apart joined without stairs; measuring %zu\n\n", pairs.size(), min_distance, n);

  std::vector<double> graph_us, rrt_ms, graph_over_rrt, graph_over_line, rrt_over_line;
  size_t rrt_found = 0, blocked = 0;
  std::printf("%6s %6s %9s %9s %9s %10s %10s %s\n", "from", "to", "line m", "graph m", "RRT m", "graph us", "RRT ms",
              "RRT status");
  for (auto [a, b] : pairs) {
    constexpr int kRepeats = 200;  // one route takes microseconds: time many
    auto t0 = Clock::now();
    std::optional<TopoRoute> r;
    for (int k = 0; k < kRepeats; ++k) r = g.route(a, b, wheeled);
    const double us = std::chrono::duration<double, std::micro>(Clock::now() - t0).count() / kRepeats;
    const Point pa = g.node(a).pos, pb = g.node(b).pos;
    const double line = distance(pa, pb);
    const PlanResult p = planner.plan(pa, pb);
    graph_us.push_back(us);
    graph_over_line.push_back(r->length / line);
    std::printf("%6d %6d %9.1f %9.1f %9.1f %10.1f %10.1f %s\n", a, b, line, r->length, p.path ? p.length : NAN, us,
                1e3 * p.seconds, std::string(to_string(p.status)).c_str());
    if (p.status == PlanStatus::StartBlocked || p.status == PlanStatus::GoalBlocked) ++blocked;
    if (!p.path) continue;
    ++rrt_found;
    rrt_ms.push_back(1e3 * p.seconds);
    graph_over_rrt.push_back(r->length / p.length);
    rrt_over_line.push_back(p.length / line);
  }
  std::printf("\n%zu long trips: graph route found for all; RRT-Connect found %zu (%zu with start or goal blocked)\n", n,
              rrt_found, blocked);
  std::printf("median time: graph route %.1f us, RRT-Connect + smoothing %.1f ms\n", median(graph_us), median(rrt_ms));
  std::printf("median length: graph / straight line %.3f, RRT / straight line %.3f, graph / RRT %.3f\n",
              median(graph_over_line), median(rrt_over_line), median(graph_over_rrt));
  SUCCEED();
}

}  // namespace
}  // namespace fleetmap
