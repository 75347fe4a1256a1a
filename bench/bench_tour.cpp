// bench-tour: topological maps acquired on a simulated guided tour (seed 003 §III-IV)
// against the hand-made navigation graph of the same floor. The tour is generated from
// the hand-made graph (tour_plan.h: every edge out and back, events from the nodes'
// degree), walked by a simulated guide and followed by the simulated robot
// (client/sim/guided_walk.h); the builder (tour_builder.h) makes the graph from the
// events the robot reported. Baseline, same run: the same events with every node at the
// robot's pose (no placement on the map).
//
// Figures: share of hand-made nodes with an acquired node within 1, 1.5 and 2 m; edge
// agreement (hand-made edges whose matched ends are joined in the acquired graph);
// route lengths between every pair of matched nodes, acquired / hand-made.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "app/maps_dir.h"
#include "client/sim/guided_walk.h"
#include "common/io/read_map_file.h"
#include "common/io/topo_json.h"
#include "common/io/tour_json.h"
#include "common/planning/tour_builder.h"
#include "common/planning/tour_plan.h"

using namespace fleetmap;

namespace {

struct Figures {
  double within[3] = {0, 0, 0};  // 1, 1.5, 2 m
  double mean_offset = 0;        // metres, hand-made node to its nearest acquired node
  double edges = 0;              // share of hand-made edges kept
  double route_ratio_mean = 0, route_ratio_worst = 1;  // acquired / hand-made; worst: farthest from 1
  size_t routes = 0, nodes = 0, acquired_edges = 0;
  double build_ms = 0;
};

Figures compare(const TopoGraph& hand, const TourGraph& t, double build_ms) {
  Figures f;
  f.build_ms = build_ms;
  const TopoGraph& a = t.graph;
  f.nodes = a.nodes().size();
  f.acquired_edges = a.edges().size();
  std::map<int, int> match;  // hand id -> acquired id, within 1.5 m
  const double radii[3] = {1.0, 1.5, 2.0};
  for (const TopoNode& h : hand.nodes()) {
    double best = std::numeric_limits<double>::infinity();
    int id = -1;
    for (const TopoNode& n : a.nodes())
      if (double d = distance(h.pos, n.pos); d < best) best = d, id = n.id;
    for (int k = 0; k < 3; ++k) f.within[k] += best <= radii[k];
    f.mean_offset += best;
    if (best <= 1.5) match[h.id] = id;
  }
  const double n = static_cast<double>(hand.nodes().size());
  for (double& w : f.within) w /= n;
  f.mean_offset /= n;
  auto joined = [&](int x, int y) {
    for (const TopoEdge& e : a.edges())
      if ((e.a == x && e.b == y) || (e.a == y && e.b == x)) return true;
    return false;
  };
  for (const TopoEdge& e : hand.edges())
    f.edges += match.count(e.a) && match.count(e.b) && joined(match[e.a], match[e.b]);
  f.edges /= static_cast<double>(hand.edges().size());
  double sum = 0;
  for (auto [h1, a1] : match)
    for (auto [h2, a2] : match) {
      if (h1 >= h2 || a1 == a2) continue;
      const auto rh = hand.route(h1, h2), ra = a.route(a1, a2);
      if (!rh || !ra || rh->length <= 0) continue;
      const double r = ra->length / rh->length;
      sum += r;
      ++f.routes;
      if (std::abs(r - 1) > std::abs(f.route_ratio_worst - 1)) f.route_ratio_worst = r;
    }
  f.route_ratio_mean = f.routes ? sum / static_cast<double>(f.routes) : NAN;
  return f;
}

void print(const char* what, const Figures& f) {
  std::printf("%-22s %5.1f %% %5.1f %% %5.1f %%  %5.2f m  %5.1f %%  %4zu / %-4zu  %6.4f  %6.4f  %5zu  %7.1f\n", what,
              100 * f.within[0], 100 * f.within[1], 100 * f.within[2], f.mean_offset, 100 * f.edges, f.nodes,
              f.acquired_edges, f.route_ratio_mean, f.route_ratio_worst, f.routes, f.build_ms);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app("bench-tour: a topological map acquired on a simulated guided tour vs the hand-made graph");
  std::string map_file = real_map_path("GDC1.vectormap.txt");
  std::string nav_file = real_map_path("GDC1.navigation.json");
  std::string write_tour;
  double merge = 1.5, keep = 0.5;
  int start = -1;
  GuidedWalkOptions walk_options;
  walk_options.max_time_s = 1e6;  // a campus tour takes more than an hour
  app.add_option("--map", map_file, "segment map (AMRL .vectormap.txt or seed .map)")->capture_default_str();
  app.add_option("--graph", nav_file, "hand-made navigation graph (JSON)")->capture_default_str();
  app.add_option("--start", start, "node the tour starts at (default: the first edge's first end)");
  app.add_option("--merge", merge, "merge distance (m)")->capture_default_str();
  app.add_option("--keep-right", keep, "metres the guide walks right of the graph's lines (0: on them)")
      ->capture_default_str();
  app.add_option("--follow", walk_options.follow_distance, "robot-guide distance (m)")->capture_default_str();
  app.add_option("--write-tour", write_tour, "also write the generated tour file (fleetmap-robot --tour)");
  app.footer("Real maps are read from $FLEETMAP_MAPS_DIR (default " + maps_dir() + ").");
  CLI11_PARSE(app, argc, argv);

  const Map map = read_map_file(map_file);
  const TopoGraph hand = read_topo_json_file(nav_file);
  if (start < 0) start = hand.edges().empty() ? hand.nodes().front().id : hand.edges().front().a;
  const std::vector<TourWaypoint> tour = keep_right(tour_of_graph(hand, start), keep);
  if (!write_tour.empty()) {
    std::FILE* out = std::fopen(write_tour.c_str(), "w");
    if (!out) return 1;
    std::fputs(write_tour_json(tour).c_str(), out);
    std::fclose(out);
  }
  GuidedWalk walk(tour, walk_options);
  std::vector<TourEvent> events;
  while (!walk.done())
    for (TourEvent& e : walk.step()) events.push_back(std::move(e));
  std::printf("%s: %zu hand-made nodes, %zu edges; tour of %zu waypoints %.2f m right of the lines, %.0f m, "
              "walked in %.0f s simulated; %zu events\n",
              nav_file.c_str(), hand.nodes().size(), hand.edges().size(), tour.size(), keep, walk.trail_length(),
              walk.time_s(), events.size());

  auto timed = [&](bool measure) {
    const auto t0 = std::chrono::steady_clock::now();
    TourGraph t = build_tour_graph(map, events, {.merge_distance = merge, .measure = measure});
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    return compare(hand, t, ms);
  };
  const Figures placed = timed(true), at_pose = timed(false);
  std::printf("%-22s %7s %7s %7s  %7s  %7s  %11s  %6s  %6s  %5s  %7s\n", "", "<=1m", "<=1.5m", "<=2m", "offset",
              "edges", "nodes/edges", "route", "worst", "pairs", "ms");
  print("placed on the map", placed);
  print("baseline: at the pose", at_pose);
  std::printf("ratio placed / baseline: offset %.2f, nodes within 1 m %.2f\n",
              at_pose.mean_offset > 0 ? placed.mean_offset / at_pose.mean_offset : NAN,
              at_pose.within[0] > 0 ? placed.within[0] / at_pose.within[0] : NAN);
  return 0;
}
