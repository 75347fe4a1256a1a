// Path planning benchmark (SPEC 7, 8): RRT-Connect + smoothing (MapPlanner) on the campus
// map against the reference grid A* (common/planning/grid_astar.h), measured in the same run, for
// random start/goal pairs that A* can join (so a path surely exists, grid_astar.h):
// planning time (median, p95) of both, and the smoothed length over A*'s length.
// A* carries the 8-connected grid's detour; "A* shortcut" (A*'s path through the same
// smoother) is the tighter, any-angle reference, printed beside it.
// Targets: median planning time <= 100 ms, length ratio <= 1.1.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "app/maps_dir.h"
#include "common/io/read_map_file.h"
#include "common/planning/grid_astar.h"
#include "common/planning/map_planner.h"
#include "common/io/map_svg.h"

namespace {

using namespace fleetmap;
using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point t0) { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }

// The q-quantile (0..1) by nearest rank.
double quantile(std::vector<double> v, double q) {
  if (v.empty()) return NAN;
  std::sort(v.begin(), v.end());
  const size_t k = static_cast<size_t>(std::ceil(q * v.size()));
  return v[std::clamp<size_t>(k, 1, v.size()) - 1];
}

struct Pair {
  Point start, goal;
  double astar_ms, astar_length, astar_shortcut_length;
};

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"bench-planner: RRT-Connect + smoothing vs grid A* on the same random reachable pairs"};
  std::string map_path = real_map_path("UT_Campus.vectormap.txt");
  size_t pairs_n = 200;
  double resolution = 0.2;
  unsigned seed = 1;
  PlannerOptions po;
  app.add_option("--map", map_path, "AMRL vector map (.vectormap.txt) or seed map")->capture_default_str();
  app.add_option("--pairs", pairs_n, "start/goal pairs")->capture_default_str();
  app.add_option("--radius", po.radius, "robot radius, metres")->capture_default_str();
  app.add_option("--resolution", resolution, "A* grid cell, metres")->capture_default_str();
  app.add_option("--seed", seed, "of the pairs and of the planner")->capture_default_str();
  app.add_option("--step", po.rrt.step, "RRT-Connect step, metres")->capture_default_str();
  app.add_option("--goal-bias", po.rrt.goal_bias, "RRT-Connect goal bias")->capture_default_str();
  app.add_option("--cut-rounds", po.smoothing.cut_rounds, "corner-cutting rounds")->capture_default_str();
  app.add_flag("!--no-round", po.smoothing.round_corners, "skip corner rounding");
  app.add_option("--attempts", po.attempts, "RRT-Connect runs per query, shortest kept")->capture_default_str();
  std::string svg_worst;
  bool dump = false;
  app.add_option("--svg-worst", svg_worst, "draw the pair with the worst length ratio (SVG file)");
  app.add_flag("--dump", dump, "print every pair");
  CLI11_PARSE(app, argc, argv);

  const Map map = read_map_file(map_path);
  const Rect b = map.border.rect();
  std::printf("map %s: %zu obstacles, %zu segments, %.0f x %.0f m; robot radius %.2f m\n", map_path.c_str(),
              map.obstacles.size(), map.segment_count(), b.xmax - b.xmin, b.ymax - b.ymin, po.radius);

  auto t0 = Clock::now();
  const MapPlanner planner(map, po);
  const double planner_build = ms_since(t0);
  t0 = Clock::now();
  GridAStar astar(map, {resolution, po.radius, po.robot});
  const double astar_build = ms_since(t0);
  const ClearanceChecker& checker = planner.checker();
  std::printf("clearance index: %zu blocking segments, %.2f m cells, %zu entries, %.1f MiB, built in %.1f ms\n",
              checker.blocking_segments(), checker.cell(), checker.cell_entries(),
              checker.memory_bytes() / 1048576.0, planner_build);
  std::printf("A* grid: %d x %d cells of %.2f m, %.1f %% free, built in %.0f ms\n", astar.nx(), astar.ny(),
              resolution, 100.0 * astar.free_cells() / (double(astar.nx()) * astar.ny()), astar_build);
  std::printf("RRT-Connect: step %.1f m, goal bias %.2f, best of %d; smoothing: greedy shortcut, %d corner-cutting rounds, %s\n\n",
              po.rrt.step, po.rrt.goal_bias, po.attempts, po.smoothing.cut_rounds,
              po.smoothing.round_corners ? "corner rounding" : "no corner rounding");

  // Pairs: random clear points that A* joins.
  std::mt19937_64 rng(seed);
  const Rect fr = checker.free_rect();
  std::uniform_real_distribution<double> ux(fr.xmin, fr.xmax), uy(fr.ymin, fr.ymax);
  const PathSmoother reference_smoother(checker, po.smoothing);
  std::vector<Pair> pairs;
  size_t tried = 0;
  while (pairs.size() < pairs_n && tried < 100 * pairs_n) {
    ++tried;
    const Point s{ux(rng), uy(rng)}, g{ux(rng), uy(rng)};
    if (!checker.point_clear(s) || !checker.point_clear(g)) continue;
    t0 = Clock::now();
    const auto p = astar.solve(s, g);
    const double ms = ms_since(t0);
    if (!p) continue;
    pairs.push_back({s, g, ms, path_length(*p), path_length(reference_smoother.cut_corners(*p))});
  }
  std::printf("%zu pairs joined by A* out of %zu clear random pairs\n", pairs.size(), tried);

  std::vector<double> plan_ms, rrt_ms, astar_ms, ratio, ratio_shortcut, raw_ratio;
  std::vector<double> plan_ms_bent, ratio_bent;  // pairs that no straight segment joins
  size_t failed = 0, rounded = 0, corners = 0, rrt_vertices = 0;
  double worst = 0;
  SvgOptions svg;
  for (const Pair& q : pairs) {
    const PlanResult r = planner.plan(q.start, q.goal);
    astar_ms.push_back(q.astar_ms);
    if (dump)
      std::printf("(%.1f, %.1f) -> (%.1f, %.1f): A* %.1f m %.1f ms, A* shortcut %.1f m, RRT %s %.1f m %.2f ms\n",
                  q.start.x, q.start.y, q.goal.x, q.goal.y, q.astar_length, q.astar_ms, q.astar_shortcut_length,
                  std::string(to_string(r.status)).c_str(), r.length, 1e3 * r.seconds);
    if (r.path && !svg_worst.empty() && r.length / q.astar_length > worst) {
      worst = r.length / q.astar_length;
      svg.title = "worst length ratio " + std::to_string(worst);
      svg.tracks = {{"grid A*", "#1f77b4", *astar.solve(q.start, q.goal)},
                    {"RRT-Connect raw", "#aaaaaa", r.raw},
                    {"smoothed", "#d62728", *r.path}};
    }
    if (!r.path) {
      ++failed;
      continue;
    }
    plan_ms.push_back(1e3 * r.seconds);
    rrt_ms.push_back(1e3 * r.rrt.seconds);
    ratio.push_back(r.length / q.astar_length);
    ratio_shortcut.push_back(r.length / q.astar_shortcut_length);
    raw_ratio.push_back(path_length(r.raw) / q.astar_length);
    if (r.raw.size() > 2) {
      plan_ms_bent.push_back(1e3 * r.seconds);
      ratio_bent.push_back(r.length / q.astar_length);
    }
    rounded += r.smoothing.rounded;
    corners += r.smoothing.corners;
    rrt_vertices += r.rrt.start_tree + r.rrt.goal_tree;
  }
  const size_t found = pairs.size() - failed;
  std::printf("RRT-Connect found %zu of %zu (%zu failed), %.0f tree vertices on average; %zu of %zu corners rounded\n",
              found, pairs.size(), failed, found ? double(rrt_vertices) / found : 0.0, rounded, corners);
  std::printf("%zu pairs are joined by a straight segment (no search), %zu need one\n\n", found - plan_ms_bent.size(),
              plan_ms_bent.size());
  std::printf("%-46s %10s %10s %10s\n", "", "median", "p95", "max");
  auto row = [](const char* name, const std::vector<double>& v, const char* unit) {
    std::printf("%-46s %10.3f %10.3f %10.3f %s\n", name, quantile(v, 0.5), quantile(v, 0.95), quantile(v, 1.0), unit);
  };
  row("time: RRT-Connect + smoothing", plan_ms, "ms");
  row("time: RRT-Connect alone", rrt_ms, "ms");
  row("time: grid A* (baseline, same pairs)", astar_ms, "ms");
  row("time: RRT-Connect + smoothing, no straight line", plan_ms_bent, "ms");
  row("length: smoothed / A*", ratio, "");
  row("length: smoothed / A* shortcut", ratio_shortcut, "");
  row("length: raw RRT / A*", raw_ratio, "");
  row("length: smoothed / A*, no straight line", ratio_bent, "");
  if (!svg_worst.empty()) {
    std::FILE* f = std::fopen(svg_worst.c_str(), "wb");
    const std::string text = write_svg(map, svg);
    if (f) std::fwrite(text.data(), 1, text.size(), f), std::fclose(f);
  }
  const double med = quantile(plan_ms, 0.5), lr = quantile(ratio, 0.5);
  std::printf("\ngoals: median time <= 100 ms: %s (%.1f ms); length ratio <= 1.1: %s (median %.3f, p95 %.3f)\n",
              med <= 100 ? "met" : "NOT met", med, lr <= 1.1 ? "met" : "NOT met", lr, quantile(ratio, 0.95));
  return failed == 0 ? 0 : 1;
}
