// Experiment of seed 002 section 4, Fig. 8: what the robot's map handling costs
// with a zoom window (seed 002 section 3.4, client/zoom_map.h) against the whole map,
// along one drive on the campus. The seed reports 75 % (worst case) to 90 % (best) less
// time with the zoom map, the costs of checking the triggers and of the refreshes
// included.
//
// One drive (seeded) over the whole campus map (UT_Campus.vectormap.txt in maps_dir()): the
// simulated robot wanders --drive metres, odometry and laser simulated on the whole map.
// The same odometry and scans feed two particle filters (tracking, seed 000's model):
//
//   whole map   the filter's ray caster is built once over the whole map;
//   zoom window ZoomMap (window --window m square, refreshed when the filter's estimate is
//               --refresh m from the window's centre): each refresh clips the map to the
//               window (what GetMap's answer holds) and installs it (set_map: a new ray
//               caster and free space). Each step's trigger check is timed with its update.
//
// Timed per update (predict + update, plus the trigger check and any refresh for the
// window), the two filters in lockstep, for three ray casters: the robot's
// (GridRayCaster, a spatial index whose cost per ray hardly depends on the map's size),
// the seed's bounding-circle method (SeedRayCaster, seed 000: obstacles culled by their
// circles once per scan), and every segment per ray (no index: the map handled in full,
// the way seed 002's cost behaves, on --brute-particles particles because it is slow).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>

#include "app/maps_dir.h"
#include "client/sim/drive_simulator.h"
#include "client/localization/free_space.h"
#include "client/sim/laser_simulator.h"
#include "client/localization/particle_filter.h"
#include "client/zoom_map.h"
#include "common/io/read_map_file.h"
#include "common/raycast/grid_ray_caster.h"
#include "common/map/map_window.h"
#include "common/raycast/ray_rules.h"
#include "common/raycast/ray_segment.h"
#include "common/raycast/seed_ray_caster.h"

namespace {

using namespace fleetmap;
using namespace fleetmap::localization;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

struct Settings {
  std::string map = fleetmap::real_map_path("UT_Campus.vectormap.txt");
  double drive = 300;
  double window = 40, refresh = 10;
  size_t particles = 500, seed_particles = 500, brute_particles = 50;
  int threads = 1;
  int runs = 1;
  uint64_t seed = 1;
  bool skip_seed = false;
};

struct Drive {
  Pose start;
  std::vector<DriveStep> steps;
  std::vector<std::vector<double>> scans;
  std::vector<double> compass;
};

Drive make_drive(const Map& map, std::shared_ptr<const RayCaster> world, const Settings& s, uint64_t seed) {
  std::mt19937_64 rng(seed);
  LaserSimulator laser(world, LaserSimulatorOptions{}, seed + 1);
  const FreeSpace free_space(map);
  Drive d;
  d.start = pick_start_pose(free_space, *world, laser.beam_angles(), 0.5, 0.5, rng);
  WanderDriver driver(world, d.start, DriveOptions{}, seed + 2);
  std::uniform_real_distribution<double> compass_noise(-deg2rad(3.0), deg2rad(3.0));
  double driven = 0;
  for (int i = 0; driven < s.drive && i < 100000; ++i) {
    d.steps.push_back(driver.step());
    driven += d.steps.back().driven;
    d.scans.push_back(laser.scan(d.steps.back().truth));
    d.compass.push_back(normalize_angle(d.steps.back().truth.theta + compass_noise(rng)));
  }
  return d;
}

struct Timing {
  std::vector<double> updates;    // seconds per step: update (+ trigger check and refresh)
  std::vector<double> refreshes;  // seconds per refresh (clip + set_map)
  std::vector<size_t> segments;   // segments the filter holds, per step
  double build = 0;               // the first map's installation
  double sq_error = 0;
  size_t n = 0;
  double total() const {
    double t = build;
    for (double u : updates) t += u;
    return t;
  }
  double rms() const { return std::sqrt(sq_error / std::max<size_t>(n, 1)); }
};

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

double mean(const std::vector<double>& v) {
  double s = 0;
  for (double x : v) s += x;
  return v.empty() ? 0 : s / v.size();
}

// Every segment tested for every ray, no index and no culling: the map handled in full,
// as seed 002's robot handled its elements (Fig. 8: "the computed time is always constant
// due of the lack of variations in the number of elements managed"). Walls only (the
// AMRL maps have nothing else): a segment stops the ray when it is at least hL high.
class BruteRayCaster : public RayCaster {
 public:
  BruteRayCaster(const Map& map, RayCasterOptions options) : options_(options) {
    for (const Obstacle& o : map.obstacles)
      for (const Segment& g : o.segments)
        if (stops_laser(g.h, options.laser_height)) segments_.push_back(prepare_segment(g.a, g.b));
  }
  double cast_direction(Point origin, Point dir) const override {
    double best = options_.rmax;
    for (const RaySegment& g : segments_) best = std::min(best, ray_segment_distance(g, origin, dir));
    return best;
  }
  const RayCasterOptions& options() const override { return options_; }

 private:
  RayCasterOptions options_;
  std::vector<RaySegment> segments_;
};

using CasterFactory = std::function<std::shared_ptr<const RayCaster>(const Map&)>;

ParticleFilterOptions filter_options(const Settings& s, size_t particles, uint64_t seed) {
  ParticleFilterOptions o = ParticleFilterOptions::seed_model();
  o.particles = particles;
  o.threads = s.threads;
  o.seed = seed;
  return o;
}

// One filter along the drive: on the whole map (one caster, built once) or on a zoom
// window (ZoomMap decides from the filter's estimate; a refresh clips the map around it
// and installs the window: new caster and free space, particles kept).
class Tracker {
 public:
  Tracker(const Map& map, const Drive& d, const Settings& s, size_t particles, const CasterFactory& caster,
          uint64_t seed, bool zoom)
      : map_(map), s_(s), caster_(caster), zoom_(ZoomMapOptions{s.window, s.refresh, 1e18}), use_zoom_(zoom) {
    const auto t0 = Clock::now();
    if (use_zoom_) {
      window_ = window_at({d.start.x, d.start.y});
      zoom_.on_window({d.start.x, d.start.y}, 0);  // no time-out: the drive has no clock
    }
    const Map& m = use_zoom_ ? window_ : map_;
    pf_ = std::make_unique<ParticleFilter>(m, caster_(m), filter_options(s, particles, seed));
    t.build = seconds_since(t0);
    pf_->init_pose(d.start, 0.1, deg2rad(2.0));
  }

  void step(const Drive& d, size_t i) {
    const auto t0 = Clock::now();
    if (use_zoom_) {
      const Point here = pf_->estimate().pose.point();
      if (zoom_.needs_refresh(here, static_cast<double>(i)) != ZoomMap::Reason::None) {
        const auto r0 = Clock::now();
        window_ = window_at(here);
        pf_->set_map(window_, caster_(window_));
        zoom_.on_window(here, static_cast<double>(i));
        t.refreshes.push_back(seconds_since(r0));
      }
    }
    pf_->predict(d.steps[i].odometry);
    pf_->update(d.scans[i], d.compass[i]);
    t.updates.push_back(seconds_since(t0));
    t.segments.push_back(use_zoom_ ? window_.segment_count() : map_.segment_count());
    const Pose e = pf_->estimate().pose, truth = d.steps[i].truth;
    t.sq_error += std::pow(e.x - truth.x, 2) + std::pow(e.y - truth.y, 2), ++t.n;
  }

  Timing t;

 private:
  Map window_at(Point c) const { return clip_map(map_, window_rect(map_.border, c, s_.window, s_.window)); }

  const Map& map_;
  const Settings& s_;
  CasterFactory caster_;
  ZoomMap zoom_;
  bool use_zoom_;
  Map window_;
  std::unique_ptr<ParticleFilter> pf_;
};

// Both filters in lockstep, in alternating order, so that whatever else runs on the
// machine weighs on both columns alike.
std::pair<Timing, Timing> run_pair(const Map& map, const Drive& d, const Settings& s, size_t particles,
                                   const CasterFactory& caster, uint64_t seed) {
  Tracker whole(map, d, s, particles, caster, seed, false), zoom(map, d, s, particles, caster, seed, true);
  for (size_t i = 0; i < d.steps.size(); ++i) {
    if (i % 2 == 0) whole.step(d, i), zoom.step(d, i);
    else zoom.step(d, i), whole.step(d, i);
  }
  return {whole.t, zoom.t};
}

void report(const char* caster, size_t particles, const Timing& whole, const Timing& zoom) {
  std::vector<double> seg_w(whole.segments.begin(), whole.segments.end()), seg_z(zoom.segments.begin(), zoom.segments.end());
  auto row = [&](const char* what, const Timing& t, const std::vector<double>& segs) {
    std::printf("  %-28s %-11s %9.2f ms %9.2f ms %6zu %9.2f ms %9.2f s %9.0f %8.3f m\n", caster, what,
                1e3 * median(t.updates), 1e3 * mean(t.updates), t.refreshes.size(), 1e3 * median(t.refreshes),
                t.total(), median(segs), t.rms());
  };
  row("whole map", whole, seg_w);
  row("zoom window", zoom, seg_z);
  const double r_med = median(zoom.updates) / median(whole.updates), r_tot = zoom.total() / whole.total();
  std::printf("  %-28s NP %zu: zoom / whole, median update %.2fx (%.0f %% less), total %.2fx (%.0f %% less); seed 002 "
              "Fig. 8: 75-90 %% less\n",
              caster, particles, r_med, 100 * (1 - r_med), r_tot, 100 * (1 - r_tot));
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"experiment-zoom: seed 002 Fig. 8, the robot's map handling (particle filter updates, window "
               "refreshes) with a zoom window vs the whole campus map, same drive"};
  Settings s;
  app.add_option("--map", s.map, "the campus (AMRL .vectormap.txt or seed .map)")->capture_default_str();
  app.add_option("--runs", s.runs, "seeded drives")->capture_default_str()->check(CLI::PositiveNumber);
  app.add_option("--seed", s.seed, "seed of every random draw")->capture_default_str();
  app.add_option("--drive", s.drive, "metres per drive")->capture_default_str()->check(CLI::PositiveNumber);
  app.add_option("--window", s.window, "side of the zoom window (m)")->capture_default_str()->check(CLI::PositiveNumber);
  app.add_option("--refresh", s.refresh, "new window when this far from its centre (m)")->capture_default_str();
  app.add_option("--particles", s.particles, "NP with the fast caster")->capture_default_str();
  app.add_option("--seed-particles", s.seed_particles, "NP with the seed's bounding-circle caster")->capture_default_str();
  app.add_option("--threads", s.threads, "filter threads")->capture_default_str()->check(CLI::PositiveNumber);
  app.add_option("--brute-particles", s.brute_particles, "NP with the every-segment caster (0: skip it)")
      ->capture_default_str();
  app.add_flag("--skip-seed", s.skip_seed, "skip the seed's bounding-circle caster");
  CLI11_PARSE(app, argc, argv);
  std::setvbuf(stdout, nullptr, _IOLBF, 0);  // a table line as soon as it is known, also into a pipe
  const Map map = read_map_file(s.map);
  const RayCasterOptions laser{0.3, 15.0};
  std::shared_ptr<const RayCaster> world = std::make_shared<GridRayCaster>(map, laser);
  const Rect b = map.border.rect();
  std::printf("seed 002 Fig. 8: %s, %zu obstacles, %zu segments, %.0f m x %.0f m; zoom window %g m x %g m (%.2f %% of "
              "the area), new window at %g m from its centre; filter: seed 000 eq. 4-6, NL 131, %d thread(s)\n",
              s.map.c_str(), map.obstacles.size(), map.segment_count(), b.xmax - b.xmin, b.ymax - b.ymin, s.window,
              s.window, 100 * s.window * s.window / ((b.xmax - b.xmin) * (b.ymax - b.ymin)), s.refresh, s.threads);
  const CasterFactory fast = [&](const Map& m) { return std::make_shared<GridRayCaster>(m, laser); };
  const CasterFactory seed = [&](const Map& m) { return std::make_shared<SeedRayCaster>(m, laser); };
  for (int run = 0; run < s.runs; ++run) {
    const uint64_t rs = s.seed * 1000003 + static_cast<uint64_t>(run) * 7919;
    const Drive d = make_drive(map, world, s, rs);
    std::printf("\nrun %d: %.0f m drive, %zu updates, start (%.1f, %.1f)\n", run + 1, s.drive, d.steps.size(), d.start.x,
                d.start.y);
    std::printf("  %-28s %-11s %12s %12s %6s %12s %11s %9s %10s\n", "ray caster", "map", "median upd", "mean upd",
                "refr.", "median refr", "total", "segments", "RMS error");
    const auto [fw, fz] = run_pair(map, d, s, s.particles, fast, rs + 5);
    report("GridRayCaster (the robot's)", s.particles, fw, fz);
    if (!s.skip_seed) {
      const auto [sw, sz] = run_pair(map, d, s, s.seed_particles, seed, rs + 5);
      report("SeedRayCaster (the seed's)", s.seed_particles, sw, sz);
    }
    if (s.brute_particles > 0) {
      const CasterFactory brute = [&](const Map& m) { return std::make_shared<BruteRayCaster>(m, laser); };
      const auto [bw, bz] = run_pair(map, d, s, s.brute_particles, brute, rs + 5);
      report("every segment (no index)", s.brute_particles, bw, bz);
    }
  }
  return 0;
}
