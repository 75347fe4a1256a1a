// Graph + RRT vs whole-map RRT (SPEC 7; seed 003 §II): the same trips planned by
// TopoPlanner (connect to the navigation graph, A* on it, RRT-Connect legs between its
// nodes, smoothing) and by the baseline, MapPlanner on the whole map (RRT-Connect +
// smoothing, what GetPath did before), in the same run with the server's planner
// options (1 s limit, 8 attempts). Trips are binned by straight-line distance; per bin:
// success of each, time median and p95 of each, and the length ratio graph / baseline
// on the trips both found. What GetPath's distance rule (topo_path_min_m) is chosen from.
//
// A trip's ends are drawn a few metres off two graph nodes that the graph joins (for
// this robot), each end in sight of its node: a path surely exists, so a failure is the
// planner's, not the trip's.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "app/exit_codes.h"
#include "app/maps_dir.h"
#include "app/run_program.h"
#include "common/io/amrl_import.h"
#include "common/io/seed_format.h"
#include "common/io/topo_json.h"
#include "common/planning/map_planner.h"
#include "common/planning/topo_planner.h"

namespace {

using namespace fleetmap;

struct Settings {
  std::string map = real_map_path("UT_Campus.vectormap.txt");
  std::string graph = real_map_path("UT_Campus.navigation.json");
  double radius = 0.3;
  double spread = 10;      // metres: how far off its node a trip's end may be
  size_t trips = 20;       // per distance bin
  unsigned seed = 5;
  bool stairs = false;
};

double quantile(std::vector<double> v, double q) {
  if (v.empty()) return NAN;
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, static_cast<size_t>(q * v.size()))];
}

struct Bin {
  double lo, hi;
  std::vector<std::pair<Point, Point>> trips;
};

int run(const Settings& s) {
  const Map map = s.map.ends_with(".vectormap.txt") ? read_amrl_file(s.map, AmrlOptions{}) : read_seed_file(s.map);
  const TopoGraph g = read_topo_json_file(s.graph);
  PlannerOptions po;  // as server_planner_options (server/core/planner_cache.h)
  po.radius = s.radius;
  po.robot.can_climb_stairs = s.stairs;
  po.rrt.max_time = 1.0;
  po.seed = s.seed;
  const MapPlanner planner(map, po);
  const TopoPlanner topo(planner, g);
  const ClearanceChecker& checker = planner.checker();

  std::vector<Bin> bins{{0, 20, {}}, {20, 60, {}}, {60, 150, {}}, {150, INFINITY, {}}};
  std::mt19937_64 rng(s.seed);
  std::uniform_int_distribution<size_t> pick(0, g.nodes().size() - 1);
  std::uniform_real_distribution<double> off(-s.spread, s.spread);
  auto near = [&](const TopoNode& n) -> std::optional<Point> {
    const Point p{n.pos.x + off(rng), n.pos.y + off(rng)};
    if (!checker.point_clear(n.pos) || !checker.point_clear(p) || !checker.motion_clear(p, n.pos)) return std::nullopt;
    return p;
  };
  for (size_t tries = 0; tries < 2000000; ++tries) {
    const TopoNode &a = g.nodes()[pick(rng)], &b = g.nodes()[pick(rng)];
    const std::optional<Point> p = near(a), q = near(b);
    if (!p || !q) continue;
    const double d = distance(*p, *q);
    Bin& bin = *std::find_if(bins.begin(), bins.end(), [&](const Bin& x) { return d < x.hi; });
    if (bin.trips.size() >= s.trips || !g.route(a.id, b.id, topo.route_options())) continue;
    bin.trips.push_back({*p, *q});
    if (std::all_of(bins.begin(), bins.end(), [&](const Bin& x) { return x.trips.size() >= s.trips; })) break;
  }

  std::printf("map %s, graph %s (%zu nodes, %zu edges), radius %.2f m%s, seed %u\n", s.map.c_str(), s.graph.c_str(),
              g.nodes().size(), g.edges().size(), s.radius, s.stairs ? ", climbs stairs" : "", s.seed);
  std::printf("%-12s %5s | %-9s %-9s | %-19s %-19s | %-10s %-17s\n", "line m", "trips", "found G", "found RRT",
              "G ms med / p95", "RRT ms med / p95", "time G/RRT", "len G/RRT med/p95");
  for (const Bin& bin : bins) {
    std::vector<double> gt, rt, time_ratio, len_ratio;
    size_t gf = 0, rf = 0;
    for (auto [p, q] : bin.trips) {
      const TopoPlanResult a = topo.plan(p, q);
      const PlanResult b = planner.plan(p, q);
      gt.push_back(1e3 * a.seconds);
      rt.push_back(1e3 * b.seconds);
      time_ratio.push_back(a.seconds / b.seconds);
      gf += a.path.has_value();
      rf += b.path.has_value();
      if (a.path && b.path) len_ratio.push_back(a.length / b.length);
    }
    char range[32];
    std::snprintf(range, sizeof range, std::isinf(bin.hi) ? ">= %.0f" : "%.0f-%.0f", bin.lo, bin.hi);
    std::printf("%-12s %5zu | %4zu      %4zu      | %7.1f / %7.1f   %7.1f / %7.1f   | %8.3f   %6.3f / %6.3f\n",
                range, bin.trips.size(), gf, rf, quantile(gt, 0.5), quantile(gt, 0.95), quantile(rt, 0.5),
                quantile(rt, 0.95), quantile(time_ratio, 0.5), quantile(len_ratio, 0.5), quantile(len_ratio, 0.95));
  }
  std::printf("(ratios: medians of per-trip ratios; G = graph + RRT legs, RRT = whole-map RRT-Connect, the baseline)\n");
  return exit_code::kOk;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"bench-topo-path: graph + RRT legs vs whole-map RRT-Connect on the same trips, by distance"};
  Settings s;
  app.add_option("--map", s.map, "vector map (AMRL .vectormap.txt or seed .map)")->capture_default_str();
  app.add_option("--graph", s.graph, "navigation graph of the same place (JSON)")->capture_default_str();
  app.add_option("--radius", s.radius, "robot radius, metres")->check(CLI::NonNegativeNumber)->capture_default_str();
  app.add_option("--spread", s.spread, "how far off its graph node a trip end may be, metres")
      ->check(CLI::PositiveNumber)->capture_default_str();
  app.add_option("--trips", s.trips, "trips per distance bin")->check(CLI::Range(1, 10000))->capture_default_str();
  app.add_option("--seed", s.seed, "of the trips and of the planners")->capture_default_str();
  app.add_flag("--stairs", s.stairs, "the robot climbs stairs (default: wheeled)");
  app.footer("Real maps are read from $FLEETMAP_MAPS_DIR (default " + maps_dir() + ").\n"
             "Exit codes: 0 ok, 1 I/O, 2 malformed map or graph, 64 usage.");
  return run_program("bench-topo-path", app, argc, argv, [&] { return run(s); });
}
