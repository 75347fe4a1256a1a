// Map import and window-query benchmark (SPEC 8, 9). Builds a ~1 M-segment
// map by tiling the campus map, imports it in one transaction, then answers random
// 100 m x 100 m windows with the spatial index and, as the baseline, with a full scan
// of the same map, in the same run. Driven by scripts/bench-map.sh (private MariaDB).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <random>
#include <vector>

#include <CLI/CLI.hpp>

#include "app/maps_dir.h"
#include "common/io/amrl_import.h"
#include "common/map/map_window.h"
#include "protocol/connection.h"
#include "protocol/map_store.h"

namespace {

using Clock = std::chrono::steady_clock;
double ms_since(Clock::time_point t0) { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }

double percentile(std::vector<double> v, double p) {
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, static_cast<size_t>(p * (v.size() - 1) + 0.5))];
}

// tiles x tiles copies of m side by side; obstacle ids stay unique.
fleetmap::Map tile(const fleetmap::Map& m, int tiles) {
  using namespace fleetmap;
  const Rect r = m.border.rect();
  const double w = r.xmax - r.xmin, h = r.ymax - r.ymin;
  Map out;
  out.border = Border::from_rect({r.xmin, r.ymin, r.xmin + tiles * w, r.ymin + tiles * h});
  int id = 1;
  for (int ty = 0; ty < tiles; ++ty)
    for (int tx = 0; tx < tiles; ++tx)
      for (const Obstacle& o : m.obstacles) {
        Obstacle c = o;
        c.id = id++;
        for (Segment& s : c.segments) {
          s.a = s.a + Point{tx * w, ty * h};
          s.b = s.b + Point{tx * w, ty * h};
        }
        c.compute_bound();
        out.obstacles.push_back(std::move(c));
      }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace fleetmap;
  CLI::App app{"bench-map: import a tiled ~1 M-segment map, then time window queries (index vs full scan)"};
  std::string campus = real_map_path("UT_Campus.vectormap.txt");
  int tiles = 26, windows = 200;
  double size = 100;
  unsigned seed = 7;
  app.add_option("--map", campus, "AMRL map to tile")->capture_default_str();
  app.add_option("--tiles", tiles, "tiles per side (26 x 26 campus maps = 1.04 M segments)")->capture_default_str();
  app.add_option("--windows", windows, "random windows")->capture_default_str();
  app.add_option("--size", size, "window side (m)")->capture_default_str();
  app.add_option("--seed", seed, "random seed")->capture_default_str();
  CLI11_PARSE(app, argc, argv);

  try {
    const Map big = tile(read_amrl_file(campus, AmrlOptions{}), tiles);
    const size_t n = big.segment_count();
    auto conn = connect(load_settings(Role::Operator, std::nullopt));
    MapStore store(*conn);

    std::printf("map: %d x %d tiles of %s = %zu segments, %zu obstacles\n", tiles, tiles, campus.c_str(), n,
                big.obstacles.size());
    // A map left by an earlier run is deleted first, outside the timed import.
    auto t0 = Clock::now();
    if (store.remove("bench_tiled")) std::printf("deleted the previous bench_tiled map in %.1f s\n", ms_since(t0) / 1000);
    t0 = Clock::now();
    int last = -1;
    store.import(big, "bench_tiled", campus, false, [&](size_t done, size_t total) {
      const int pct = static_cast<int>(100 * done / total);
      if (pct / 10 != last / 10) std::fprintf(stderr, "  import %3d%%  %.1f s\n", pct, ms_since(t0) / 1000);
      last = pct;
    });
    const double import_s = ms_since(t0) / 1000;
    std::printf("import: %.1f s, %.0f segments/s   (goal <= 30 s)\n", import_s, n / import_s);

    std::mt19937 rng(seed);
    const Rect b = big.border.rect();
    std::uniform_real_distribution<double> ux(b.xmin + size / 2, b.xmax - size / 2), uy(b.ymin + size / 2, b.ymax - size / 2);
    std::vector<double> indexed, scanned;
    size_t rows = 0;
    for (int i = 0; i < windows; ++i) {
      const Rect r = window_rect(big.border, {ux(rng), uy(rng)}, size, size);
      auto t = Clock::now();
      const Map a = store.window("bench_tiled", r, WindowAccess::SpatialIndex);
      indexed.push_back(ms_since(t));
      t = Clock::now();
      const Map f = store.window("bench_tiled", r, WindowAccess::FullScan);
      scanned.push_back(ms_since(t));
      if (!(a == f)) {
        std::fprintf(stderr, "bench-map: index and full scan disagree on window %d\n", i);
        return 1;
      }
      rows += a.segment_count();
    }
    const double mi = percentile(indexed, 0.5), ms = percentile(scanned, 0.5);
    std::printf("window %gx%g m, %d random windows, %.1f segments on average\n", size, size, windows,
                static_cast<double>(rows) / windows);
    std::printf("  spatial index: median %.2f ms, p95 %.2f ms   (goal <= 3 ms; SPEC 9: MariaDB alone ~2-3 ms)\n", mi,
                percentile(indexed, 0.95));
    std::printf("  full scan:     median %.2f ms, p95 %.2f ms   (baseline; SPEC 9: ~220 ms)\n", ms,
                percentile(scanned, 0.95));
    std::printf("  ratio full scan / index: %.0fx   (goal >= 100x)\n", ms / mi);
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench-map: %s\n", e.what());
    return 1;
  }
}
