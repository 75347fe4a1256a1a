// Ray casting benchmark (SPEC 6, 8). On the dense floor (GDC1) and on the campus, in
// the same run with the seed's parameters (RMAX 15 m, NL 131 beams over 180 degrees,
// hL 0.3 m) from random poses: the seed's bounding-circle method (SeedRayCaster), the
// first sweep ("before": SweepRayCaster with 4 m cells, every wall within reach,
// per-beam kernel), the previous default ("previous": 1 m cells where the map is dense,
// 32 occluders; --previous-cell, --previous-occluders) and the fast caster
// (make_fast_ray_caster's SweepRayCaster: cells picked by density, occlusion-culled
// lists, batched kernel): rays/s on 1 and 2 threads, ratios, one particle-filter update
// (NP 6000 poses x NL 131 rays) in Hz, and each structure's memory and build time. The
// sweeps are timed in turns, run after run, so that a change of load touches each
// alike. Targets on GDC1: >= 150 M rays/s on 2 cores, update >= 200 Hz, structure
// < 64 MiB; on the campus, no slower than before.
//
// The machine is shared: besides wall-clock rates (best of --repeats runs) it prints
// rays per CPU-second of the casting threads, which other work disturbs much less;
// "CPU-bound" figures are those times the threads, as if each had its core.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <memory>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "app/maps_dir.h"
#include "common/io/read_map_file.h"
#include "common/raycast/grid_ray_caster.h"
#include "common/raycast/seed_ray_caster.h"
#include "common/raycast/sweep_ray_caster.h"

namespace {

using namespace fleetmap;
using Clock = std::chrono::steady_clock;
constexpr double kPi = 3.14159265358979323846;

struct Pose {
  Point p;
  double theta;
};

std::vector<Pose> random_poses(const Map& m, size_t n, unsigned seed) {
  std::mt19937_64 rng(seed);
  const Rect r = m.border.rect();
  std::uniform_real_distribution<double> ux(r.xmin, r.xmax), uy(r.ymin, r.ymax), ua(-kPi, kPi);
  std::vector<Pose> out(n);
  for (Pose& q : out) q = {{ux(rng), uy(rng)}, ua(rng)};
  return out;
}

double thread_cpu_seconds() {
  timespec ts;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

struct Timing {
  double wall = 0;  // seconds
  double cpu = 0;   // seconds, summed over the threads
};

// One scan from each pose, the poses dealt round-robin to `threads` threads.
Timing time_scans(const RayCaster& rc, const std::vector<Pose>& poses, const std::vector<double>& beams, int threads) {
  std::vector<double> cpu(threads, 0), sums(threads, 0);
  const auto t0 = Clock::now();
  std::vector<std::thread> pool;
  for (int k = 0; k < threads; ++k)
    pool.emplace_back([&, k] {
      const double c0 = thread_cpu_seconds();
      std::vector<double> ranges(beams.size());
      double s = 0;
      for (size_t i = k; i < poses.size(); i += threads) {
        rc.cast_scan(poses[i].p, poses[i].theta, beams, ranges.data());
        s += ranges[i % beams.size()];
      }
      sums[k] = s;
      cpu[k] = thread_cpu_seconds() - c0;
    });
  for (auto& t : pool) t.join();
  Timing t{std::chrono::duration<double>(Clock::now() - t0).count(), 0};
  for (double c : cpu) t.cpu += c;
  if (sums[0] == 12345.678) std::puts("");  // keep the work observable
  return t;
}

struct Rate {
  double wall = 0;  // M rays/s, best run
  double cpu = 0;   // M rays per CPU-second, best run
};

// Each caster's best of `repeats` runs, the casters taking turns within each run.
std::vector<Rate> rates(const std::vector<const RayCaster*>& casters, const std::vector<Pose>& poses,
                        const std::vector<double>& beams, int threads, int repeats) {
  std::vector<Rate> best(casters.size());
  const double rays = static_cast<double>(poses.size() * beams.size());
  for (int r = 0; r < repeats; ++r)
    for (size_t i = 0; i < casters.size(); ++i) {
      const Timing t = time_scans(*casters[i], poses, beams, threads);
      best[i].wall = std::max(best[i].wall, rays / t.wall / 1e6);
      best[i].cpu = std::max(best[i].cpu, rays / t.cpu / 1e6);
    }
  return best;
}

Rate rate(const RayCaster& rc, const std::vector<Pose>& poses, const std::vector<double>& beams, int threads,
          int repeats) {
  return rates({&rc}, poses, beams, threads, repeats)[0];
}

// Single rays (cast) from the poses, one thread: M rays per CPU-second.
double single_rate(const RayCaster& rc, const std::vector<Pose>& poses) {
  double sum = 0;
  const double c0 = thread_cpu_seconds();
  for (const Pose& q : poses) sum += rc.cast(q.p, q.theta);
  const double sec = thread_cpu_seconds() - c0;
  if (sum == 12345.678) std::puts("");
  return poses.size() / sec / 1e6;
}

double mib(size_t bytes) { return bytes / (1024.0 * 1024.0); }

void row(const std::string& name, Rate one, Rate many, const std::string& note) {
  std::printf("%-40s %9.2f M %9.2f M %9.2f M   %s\n", name.c_str(), one.wall, many.wall, one.cpu, note.c_str());
}

struct Update {
  double hz_median = 0, hz_best = 0, hz_cpu = 0;
};

// One particle-filter update: NP scans from NP poses on `threads` threads, for each
// caster, the casters taking turns.
std::vector<Update> filter_updates(const std::vector<const RayCaster*>& casters, const std::vector<Pose>& pf,
                                   const std::vector<double>& beams, int threads, int repeats) {
  std::vector<std::vector<double>> wall(casters.size());
  std::vector<double> cpu_best(casters.size(), 1e300);
  for (int r = 0; r < std::max(3, 2 * repeats); ++r)
    for (size_t i = 0; i < casters.size(); ++i) {
      const Timing t = time_scans(*casters[i], pf, beams, threads);
      wall[i].push_back(t.wall);
      cpu_best[i] = std::min(cpu_best[i], t.cpu);
    }
  std::vector<Update> out;
  for (size_t i = 0; i < casters.size(); ++i) {
    std::sort(wall[i].begin(), wall[i].end());
    out.push_back({1 / wall[i][wall[i].size() / 2], 1 / wall[i][0], threads / cpu_best[i]});
  }
  return out;
}

// The cell the default picked before finer cells (docs/ray-casting.md, "The sweep on
// dense floors"): 1 m where the 4 m lists would average more than 32 entries, else 4 m.
double previous_default_cell(const Map& map, const RayCasterOptions& opt) {
  const LaserObstacles obstacles = prepare_laser_obstacles(map, opt.laser_height);
  return CandidateGrid::estimate_mean_list(obstacles, 4.0, opt.rmax) > 32 ? 1.0 : 4.0;
}

struct Settings {
  RayCasterOptions opt{0.3, 15.0};
  std::vector<double> beams;
  int particles = 6000, repeats = 3, threads = 2;
  size_t poses_fast = 30000, poses_seed = 5000;
  double cell = SweepOptions{}.cell;
  double previous_cell = 0;  // 0: previous_default_cell()
  size_t occluders = SweepOptions{}.occluders, previous_occluders = 32;
  bool alternatives = false;
};

struct MapResult {
  Rate fast2, previous2, before2;
  double fast_cpu = 0, previous_cpu = 0, before_cpu = 0;  // M rays/s, 2 cores CPU-bound
  Update fast_update, previous_update, before_update;
  double fast_mib = 0, previous_mib = 0;
  double fast_build = 0, previous_build = 0;  // ms
};

template <class F>
double build_ms(F&& f) {
  const auto t0 = Clock::now();
  f();
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

MapResult bench_map(const std::string& map_path, const Settings& set) {
  const Map map = read_map_file(map_path);
  const std::vector<double>& beams = set.beams;
  const RayCasterOptions opt = set.opt;
  const int threads = set.threads, repeats = set.repeats;
  std::printf("== map %s: %zu obstacles, %zu segments; rmax %.1f m, %zu beams, hL %.2f m\n", map_path.c_str(),
              map.obstacles.size(), map.segment_count(), opt.rmax, beams.size(), opt.laser_height);

  std::unique_ptr<SeedRayCaster> seed_p;
  std::unique_ptr<SweepRayCaster> fast_p, previous_p, before_p;
  const double seed_build = build_ms([&] { seed_p = std::make_unique<SeedRayCaster>(map, opt); });
  SweepOptions fast_opt{set.cell};
  fast_opt.occluders = set.occluders;
  SweepOptions before_opt{4.0};
  before_opt.occluders = 0;
  before_opt.kernel = SweepKernel::per_beam;
  const double fast_build = build_ms([&] { fast_p = std::make_unique<SweepRayCaster>(map, opt, fast_opt); });
  const double before_build = build_ms([&] { before_p = std::make_unique<SweepRayCaster>(map, opt, before_opt); });
  SweepOptions previous_opt{set.previous_cell > 0 ? set.previous_cell : previous_default_cell(map, opt)};
  previous_opt.occluders = set.previous_occluders;
  const double previous_build =
      build_ms([&] { previous_p = std::make_unique<SweepRayCaster>(map, opt, previous_opt); });
  const SeedRayCaster& seed = *seed_p;
  const SweepRayCaster &fast = *fast_p, &previous = *previous_p, &before = *before_p;

  const std::vector<Pose> poses = random_poses(map, set.poses_fast, 1);
  const std::vector<Pose> seed_poses(poses.begin(), poses.begin() + std::min(set.poses_seed, poses.size()));

  // Same rays, same answers: the figures below compare equal work.
  size_t hits = 0, differ = 0;
  {
    std::vector<double> a(beams.size()), b(beams.size()), c(beams.size()), d(beams.size());
    for (const Pose& q : seed_poses) {
      seed.cast_scan(q.p, q.theta, beams, a.data());
      fast.cast_scan(q.p, q.theta, beams, b.data());
      before.cast_scan(q.p, q.theta, beams, c.data());
      previous.cast_scan(q.p, q.theta, beams, d.data());
      for (size_t j = 0; j < beams.size(); ++j) {
        hits += b[j] < opt.rmax;
        differ += std::fabs(a[j] - b[j]) > 1e-6 || std::fabs(a[j] - c[j]) > 1e-6 || std::fabs(a[j] - d[j]) > 1e-6;
      }
    }
  }
  std::printf("check: %zu scans, %.1f %% of rays hit something, %zu differ from the seed by > 1e-6 m\n\n",
              seed_poses.size(), 100.0 * hits / (seed_poses.size() * beams.size()), differ);

  std::printf("scans from random poses                  %11s %11s %11s\n", "1 thread", "2 threads", "per CPU-s");
  const Rate s1 = rate(seed, seed_poses, beams, 1, repeats), s2 = rate(seed, seed_poses, beams, threads, repeats);
  char note[128];
  std::snprintf(note, sizeof note, "build %.1f ms", seed_build);
  row("seed: bounding circles per scan", s1, s2, note);
  const std::vector<const RayCaster*> sweeps = {&before, &previous, &fast};
  const std::vector<Rate> one = rates(sweeps, poses, beams, 1, repeats), two = rates(sweeps, poses, beams, threads, repeats);
  const Rate b1 = one[0], b2 = two[0], p1 = one[1], p2 = two[1], f1 = one[2], f2 = two[2];
  std::snprintf(note, sizeof note, "build %.1f ms, %.2f MiB", before_build, mib(before.memory_bytes()));
  row("before: sweep, 4 m cells, per beam", b1, b2, note);
  auto cell_name = [](const SweepRayCaster& s) { return std::to_string(s.candidates().cell()).substr(0, 4) + " m"; };
  std::snprintf(note, sizeof note, "build %.1f ms, %.2f MiB", previous_build, mib(previous.memory_bytes()));
  row("previous: " + cell_name(previous) + " cells, culled, batched", p1, p2, note);
  std::snprintf(note, sizeof note, "build %.1f ms, %.2f MiB", fast_build, mib(fast.memory_bytes()));
  row("fast: sweep, " + cell_name(fast) + " cells, culled, batched", f1, f2, note);
  std::printf("%-40s %9.1f x %9.1f x %9.1f x\n", "ratio fast / before", f1.wall / b1.wall, f2.wall / b2.wall,
              f1.cpu / b1.cpu);
  std::printf("%-40s %9.2f x %9.2f x %9.2f x\n", "ratio fast / previous", f1.wall / p1.wall, f2.wall / p2.wall,
              f1.cpu / p1.cpu);
  std::printf("%-40s %9.1f x %9.1f x %9.1f x\n", "ratio fast / seed", f1.wall / s1.wall, f2.wall / s2.wall,
              f1.cpu / s1.cpu);

  if (set.alternatives) {
    std::printf("\nalternatives tried (same poses and beams)\n");
    for (double c : {0.5, 1.0, 2.0, 4.0})
      for (size_t occ : {size_t{0}, size_t{16}, size_t{32}, size_t{64}, size_t{128}})
        for (SweepKernel k : {SweepKernel::per_beam, SweepKernel::batched}) {
          if (k == SweepKernel::per_beam && occ != 0 && occ != 32) continue;
          if (c == 0.5 && occ == 0) continue;  // without culling 0.5 m lists would not fit
          SweepOptions so{c};
          so.occluders = occ;
          so.kernel = k;
          std::unique_ptr<SweepRayCaster> sw;
          const double ms = build_ms([&] { sw = std::make_unique<SweepRayCaster>(map, opt, so); });
          std::snprintf(note, sizeof note, "build %.1f ms, %.2f MiB", ms, mib(sw->memory_bytes()));
          row("sweep " + std::to_string(c).substr(0, 3) + " m, " + std::to_string(occ) + " occluders, " +
                  (k == SweepKernel::batched ? "batched" : "per beam"),
              rate(*sw, poses, beams, 1, repeats), rate(*sw, poses, beams, threads, repeats), note);
        }
    struct Alt {
      const char* name;
      GridOptions g;
    };
    for (const Alt& alt :
         {Alt{"grid walk 1 m, plain", {1.0, false}}, Alt{"grid walk 1 m, empty-space skip", {1.0, true}},
          Alt{"grid walk 2 m, empty-space skip", {2.0, true}}, Alt{"grid walk 4 m, empty-space skip", {4.0, true}}}) {
      const GridRayCaster g(map, opt, alt.g);
      std::snprintf(note, sizeof note, "%.2f MiB", mib(g.memory_bytes()));
      row(alt.name, rate(g, poses, beams, 1, repeats), rate(g, poses, beams, threads, repeats), note);
    }
  }

  // Single rays (cast): the seed culls per ray, the sweeps read one list per ray.
  {
    const std::vector<Pose> rays = random_poses(map, 200000, 2);
    const std::vector<Pose> few(rays.begin(), rays.begin() + 20000);
    const GridRayCaster grid(map, opt);
    const double seed_single = single_rate(seed, few), fast_single = single_rate(fast, rays);
    std::printf(
        "\nsingle random rays (cast), M rays per CPU-s: seed (culling per ray) %.3f, before %.2f, fast %.2f,"
        " grid walk 1 m %.2f\n",
        seed_single, single_rate(before, rays), fast_single, single_rate(grid, rays));
  }

  const std::vector<Pose> pf(poses.begin(), poses.begin() + std::min<size_t>(set.particles, poses.size()));
  const std::vector<Update> ups = filter_updates(sweeps, pf, beams, threads, repeats);
  const Update ub = ups[0], up = ups[1], uf = ups[2];
  const double seed_update_s = pf.size() * beams.size() / (s2.wall * 1e6);
  std::printf("\nfilter update, %zu poses x %zu rays on %d threads (seed %.2f Hz):\n", pf.size(), beams.size(),
              threads, 1 / seed_update_s);
  std::printf("  before   %7.1f Hz median, %7.1f Hz best, %7.1f Hz CPU-bound\n", ub.hz_median, ub.hz_best,
              ub.hz_cpu);
  std::printf("  previous %7.1f Hz median, %7.1f Hz best, %7.1f Hz CPU-bound\n", up.hz_median, up.hz_best,
              up.hz_cpu);
  std::printf("  fast     %7.1f Hz median, %7.1f Hz best, %7.1f Hz CPU-bound  (CPU-bound: %.1f x before, %.2f x "
              "previous)\n",
              uf.hz_median, uf.hz_best, uf.hz_cpu, uf.hz_cpu / ub.hz_cpu, uf.hz_cpu / up.hz_cpu);
  std::printf("fast structure: %.2f MiB (%zu cells of %.2g m, %zu list entries, %.1f per cell); before %.2f MiB\n\n",
              mib(fast.memory_bytes()), fast.candidates().cells(), fast.candidates().cell(),
              fast.candidates().entries(),
              static_cast<double>(fast.candidates().entries()) / fast.candidates().cells(), mib(before.memory_bytes()));
  std::printf("previous structure: %.2f MiB (%zu cells of %.2g m, %.1f entries per cell)\n\n",
              mib(previous.memory_bytes()), previous.candidates().cells(), previous.candidates().cell(),
              static_cast<double>(previous.candidates().entries()) / previous.candidates().cells());
  return {f2,  p2, b2, threads * f1.cpu, threads * p1.cpu, threads * b1.cpu, uf, up, ub, mib(fast.memory_bytes()),
          mib(previous.memory_bytes()), fast_build, previous_build};
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"bench-raycast: the seed's ray casting, the first sweep and the fast caster, same run"};
  std::vector<std::string> maps = {real_map_path("GDC1.vectormap.txt"), real_map_path("UT_Campus.vectormap.txt")};
  Settings set;
  int beams_n = 131;
  double fov_deg = 180;
  app.add_option("--map", maps, "AMRL vector maps (.vectormap.txt) or seed maps (.map); default GDC1 and the campus");
  app.add_option("--laser-height", set.opt.laser_height, "hL, metres")->capture_default_str();
  app.add_option("--rmax", set.opt.rmax, "metres")->capture_default_str();
  app.add_option("--beams", beams_n, "NL")->capture_default_str();
  app.add_option("--fov", fov_deg, "degrees")->capture_default_str();
  app.add_option("--particles", set.particles, "NP of the filter update")->capture_default_str();
  app.add_option("--poses", set.poses_fast, "random poses for the fast casters")->capture_default_str();
  app.add_option("--seed-poses", set.poses_seed, "random poses for the seed's method")->capture_default_str();
  app.add_option("--repeats", set.repeats, "runs per figure (best kept)")->capture_default_str();
  app.add_option("--threads", set.threads, "threads of the multi-threaded figures")->capture_default_str();
  app.add_option("--cell", set.cell, "cell of the fast caster's candidate grid, metres (0: by density)")
      ->capture_default_str();
  app.add_option("--previous-cell", set.previous_cell,
                 "cell of the previous default, timed beside (0: 1 m where dense, else 4 m)")
      ->capture_default_str();
  app.add_option("--previous-occluders", set.previous_occluders, "occluders of the previous default")
      ->capture_default_str();
  app.add_option("--occluders", set.occluders, "walls tried as occluders per cell (0: no culling)")
      ->capture_default_str();
  app.add_flag("--alternatives", set.alternatives, "also time the other designs and cell sizes tried");
  CLI11_PARSE(app, argc, argv);
  set.beams = evenly_spread_angles(beams_n, fov_deg * kPi / 180);
  std::printf("%d beams over %.0f deg; %u hardware threads\n\n", beams_n, fov_deg, std::thread::hardware_concurrency());

  std::vector<MapResult> results;
  for (const std::string& m : maps) results.push_back(bench_map(m, set));
  std::printf("summary, 2 threads: M rays/s wall (CPU-bound), filter update Hz CPU-bound\n");
  for (size_t i = 0; i < maps.size(); ++i) {
    const MapResult& r = results[i];
    std::printf("  %-50s fast %6.1f M (%6.1f M) vs before %6.1f M (%6.1f M): %.1f x; update %.0f Hz vs %.0f Hz; %.2f MiB\n",
                maps[i].c_str(), r.fast2.wall, r.fast_cpu, r.before2.wall, r.before_cpu, r.fast_cpu / r.before_cpu,
                r.fast_update.hz_cpu, r.before_update.hz_cpu, r.fast_mib);
    std::printf("  %-50s fast vs previous: %.2f x rays (CPU-bound), %.2f x update (%.0f Hz vs %.0f Hz), %.2f vs %.2f "
                "MiB, build %.0f vs %.0f ms\n",
                "", r.fast_cpu / r.previous_cpu, r.fast_update.hz_cpu / r.previous_update.hz_cpu, r.fast_update.hz_cpu,
                r.previous_update.hz_cpu, r.fast_mib, r.previous_mib, r.fast_build, r.previous_build);
  }
  const MapResult& dense = results[0];
  std::printf(
      "goal on %s: >= 150 M rays/s on %d threads: %s (%.1f M wall, %.1f M CPU-bound); update >= 200 Hz: %s (%.0f Hz"
      " best, %.0f Hz CPU-bound); < 64 MiB: %s\n",
      maps[0].c_str(), set.threads, dense.fast_cpu >= 150 ? "yes" : "no", dense.fast2.wall, dense.fast_cpu,
      dense.fast_update.hz_cpu >= 200 ? "yes" : "no", dense.fast_update.hz_best, dense.fast_update.hz_cpu,
      dense.fast_mib < 64 ? "yes" : "no");
  return 0;
}
