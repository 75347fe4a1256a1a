// Topological routing benchmark (SPEC 7, 8; seed 003): long trips on the campus routed on
// the navigation graph (TopoGraph::route, what `fleetmap topo route` answers) beside the
// baseline, planning the same trip straight on the vector map (MapPlanner: RRT-Connect +
// smoothing, what `fleetmap plan` answers), from the same start node to the same goal
// node in the same run. Prints both times and lengths, and their ratios: what a graph
// that is kept in the database buys over planning every trip from scratch, and how much
// longer its routes are, since they follow the graph's edges.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <optional>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>

#include "app/exit_codes.h"
#include "app/maps_dir.h"
#include "app/run_program.h"
#include "common/io/amrl_import.h"
#include "common/io/seed_format.h"
#include "common/io/topo_json.h"
#include "common/planning/map_planner.h"
#include "common/planning/topo_graph.h"

namespace {

using namespace fleetmap;
using Clock = std::chrono::steady_clock;

double median(std::vector<double> v) {
  if (v.empty()) return NAN;
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

struct Settings {
  std::string map = real_map_path("UT_Campus.vectormap.txt");
  std::string graph = real_map_path("UT_Campus.navigation.json");
  double radius = 0.3;         // metres, the robot's, for both
  double min_distance = 150;   // metres as the crow flies: long trips only
  size_t trips = 30;
  unsigned seed = 3;           // of the trips drawn and of the planner
  int repeats = 200;           // one route takes microseconds: time many
  bool stairs = false;         // false: a wheeled robot, stairs edges unusable
  bool per_trip = false;
};

// Node pairs at least min_distance apart that the graph joins, shuffled, the first `trips`.
std::vector<std::pair<int, int>> long_trips(const TopoGraph& g, const RouteOptions& ro, const Settings& s,
                                            size_t* candidates) {
  std::vector<std::pair<int, int>> pairs;
  for (const TopoNode& a : g.nodes())
    for (const TopoNode& b : g.nodes())
      if (a.id < b.id && distance(a.pos, b.pos) >= s.min_distance && g.route(a.id, b.id, ro))
        pairs.push_back({a.id, b.id});
  *candidates = pairs.size();
  std::mt19937 rng(s.seed);
  std::shuffle(pairs.begin(), pairs.end(), rng);
  pairs.resize(std::min(pairs.size(), s.trips));
  return pairs;
}

int run(const Settings& s) {
  const Map map = s.map.ends_with(".vectormap.txt") ? read_amrl_file(s.map, AmrlOptions{}) : read_seed_file(s.map);
  const TopoGraph g = read_topo_json_file(s.graph);
  const RouteOptions ro{.avoid_stairs = !s.stairs, .radius = s.radius};

  PlannerOptions po;
  po.radius = s.radius;
  po.seed = s.seed;
  const MapPlanner planner(map, po);
  const ClearanceChecker& checker = planner.checker();

  // How well the graph sits on the vector map for a robot of this radius: a node or edge
  // that is not clear is one the RRT could not follow either.
  size_t clear_nodes = 0, clear_edges = 0;
  for (const TopoNode& n : g.nodes()) clear_nodes += checker.point_clear(n.pos);
  for (const TopoEdge& e : g.edges()) clear_edges += checker.motion_clear(g.node(e.a).pos, g.node(e.b).pos);
  std::printf("map %s: %zu segments; graph %s: %zu nodes, %zu edges\n", s.map.c_str(), map.segment_count(),
              s.graph.c_str(), g.nodes().size(), g.edges().size());
  std::printf("graph on the map, robot radius %.2f m: %zu of %zu nodes clear, %zu of %zu edges clear\n", s.radius,
              clear_nodes, g.nodes().size(), clear_edges, g.edges().size());

  size_t candidates = 0;
  const auto trips = long_trips(g, ro, s, &candidates);
  std::printf("%zu node pairs >= %.0f m apart joined%s; measuring %zu (seed %u)\n\n", candidates, s.min_distance,
              s.stairs ? "" : " without stairs", trips.size(), s.seed);
  if (trips.empty()) {
    std::cerr << "bench-topo: no node pair of " << s.graph << " is >= " << s.min_distance
              << " m apart and joined; expected at least one (lower --min-distance)\n";
    return exit_code::kBadInput;
  }

  std::vector<double> graph_us, rrt_ms, rrt_over_graph_time, graph_over_rrt, graph_over_line, rrt_over_line;
  size_t rrt_found = 0, blocked = 0;
  if (s.per_trip)
    std::printf("%6s %6s %9s %9s %9s %10s %10s %s\n", "from", "to", "line m", "graph m", "RRT m", "graph us", "RRT ms",
                "RRT status");
  for (auto [a, b] : trips) {
    const auto t0 = Clock::now();
    std::optional<TopoRoute> r;
    for (int k = 0; k < s.repeats; ++k) r = g.route(a, b, ro);
    const double us = std::chrono::duration<double, std::micro>(Clock::now() - t0).count() / s.repeats;
    const Point pa = g.node(a).pos, pb = g.node(b).pos;
    const double line = distance(pa, pb);
    const PlanResult p = planner.plan(pa, pb);
    graph_us.push_back(us);
    graph_over_line.push_back(r->length / line);
    if (s.per_trip)
      std::printf("%6d %6d %9.1f %9.1f %9.1f %10.1f %10.1f %s\n", a, b, line, r->length, p.path ? p.length : NAN, us,
                  1e3 * p.seconds, std::string(to_string(p.status)).c_str());
    if (p.status == PlanStatus::StartBlocked || p.status == PlanStatus::GoalBlocked) ++blocked;
    if (!p.path) continue;
    ++rrt_found;
    rrt_ms.push_back(1e3 * p.seconds);
    rrt_over_graph_time.push_back(1e3 * p.seconds / (us * 1e-3));
    graph_over_rrt.push_back(r->length / p.length);
    rrt_over_line.push_back(p.length / line);
  }
  if (s.per_trip) std::printf("\n");

  std::printf("%zu long trips: graph route found for all; RRT-Connect + smoothing (the baseline) found %zu"
              " (%zu with start or goal blocked)\n\n", trips.size(), rrt_found, blocked);
  std::printf("%-24s %14s %16s %10s\n", "median of the trips", "graph route", "RRT (baseline)", "ratio");
  std::printf("%-24s %11.1f us %13.1f ms %9.0fx   (RRT time / graph time, per trip)\n", "time", median(graph_us),
              median(rrt_ms), median(rrt_over_graph_time));
  std::printf("%-24s %14.3f %16.3f %10.3f   (graph length / RRT length, per trip)\n", "length / straight line",
              median(graph_over_line), median(rrt_over_line), median(graph_over_rrt));
  return exit_code::kOk;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"bench-topo: routes on the navigation graph vs RRT-Connect + smoothing on the vector map, "
               "same long trips, same run"};
  Settings s;
  app.add_option("--map", s.map, "vector map (AMRL .vectormap.txt or seed .map)")->capture_default_str();
  app.add_option("--graph", s.graph, "navigation graph of the same place (JSON)")->capture_default_str();
  app.add_option("--radius", s.radius, "robot radius, metres")->check(CLI::NonNegativeNumber)->capture_default_str();
  app.add_option("--min-distance", s.min_distance, "shortest trip, metres as the crow flies")
      ->check(CLI::NonNegativeNumber)->capture_default_str();
  app.add_option("--trips", s.trips, "trips measured")->check(CLI::Range(1, 100000))->capture_default_str();
  app.add_option("--seed", s.seed, "of the trips drawn and of the planner")->capture_default_str();
  app.add_option("--repeats", s.repeats, "graph routes timed per trip (one takes microseconds)")
      ->check(CLI::Range(1, 1000000))->capture_default_str();
  app.add_flag("--stairs", s.stairs, "the robot climbs stairs (default: wheeled, stairs edges unusable)");
  app.add_flag("--per-trip", s.per_trip, "print every trip");
  app.footer("Real maps are read from $FLEETMAP_MAPS_DIR (default " + maps_dir() + ").\n"
             "Exit codes: 0 ok, 1 I/O, 2 malformed map or graph, or no trip that long, 64 usage.");
  return run_program("bench-topo", app, argc, argv, [&] { return run(s); });
}
