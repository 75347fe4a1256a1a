// The fast RayCasters against the seed's method (the reference, SeedRayCaster): the same
// range within 1e-6 m for 100 000 random rays (origins uniform in the border, all
// angles) and for random scans, on the real maps and the example map, at several laser
// heights. The real maps have walls of one height and no stairs or ramps, so each is
// also cast on a copy with varied wall heights and generated stairs and ramps.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "common/io/amrl_import.h"
#include "common/raycast/beam_order.h"
#include "common/raycast/grid_ray_caster.h"
#include "common/map/map_window.h"
#include "common/map/ramp.h"
#include "common/io/seed_format.h"
#include "common/raycast/seed_ray_caster.h"
#include "common/raycast/sweep_ray_caster.h"

namespace fleetmap {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kTolerance = 1e-6;  // metres
constexpr int kRays = 100000;
constexpr int kScans = 300;

const std::string kMaps = FLEETMAP_REAL_MAPS;
const std::string kExample = FLEETMAP_SOURCE_DIR "/maps/example-campus.map";

Point along(Point p, Point u, double k) { return p + k * u; }

// Stairs climbing along u from base: n steps of rise and tread 0.3 m, width w.
Obstacle generated_stairs(int id, Point base, Point u, int n, double rise, double w) {
  const Point v{-u.y, u.x};
  Obstacle o;
  o.id = id;
  o.type = ShapeType::Stairs;
  o.semantic = "stairs,generated";
  for (int k = 0; k <= n; ++k) {
    const Point mid = along(base, u, 0.3 * k);
    const Point l = along(mid, v, w / 2), r = along(mid, v, -w / 2);
    if (k < n)
      o.segments.push_back({r, l, rise * (k + 1), 1, "step", ""});
    else
      o.segments.push_back({l, r, 0, 1, "step", ""});  // closing, the other way
  }
  o.compute_bound();
  return o;
}

// A rectangular ramp rising along u from its low edge through foot: length len, width w.
Obstacle generated_ramp(int id, Point foot, Point u, double len, double w, double slope) {
  const Point v{-u.y, u.x};
  const Point p[4] = {along(foot, v, -w / 2), along(along(foot, v, -w / 2), u, len),
                      along(along(foot, v, w / 2), u, len), along(foot, v, w / 2)};
  Obstacle o;
  o.id = id;
  o.type = ShapeType::Ramp;
  o.semantic = "ramp,generated," + ramp_tokens(-slope * u.x, -slope * u.y, 1, foot);
  for (int k = 0; k < 4; ++k) o.segments.push_back({p[k], p[(k + 1) % 4], 0, 1, "edge", ""});
  o.compute_bound();
  return o;
}

// The map with wall heights drawn from {0.2, 0.6, 2, 4} m and 40 stairs and 40 ramps at
// random places, so that every laser height sees a different map.
Map varied(Map m, unsigned seed) {
  std::mt19937_64 rng(seed);
  const double heights[] = {0.2, 0.6, 2.0, 4.0};
  for (Obstacle& o : m.obstacles)
    for (Segment& s : o.segments) s.h = heights[rng() % 4];
  const Rect r = m.border.rect();
  std::uniform_real_distribution<double> ux(r.xmin + 10, r.xmax - 10), uy(r.ymin + 10, r.ymax - 10), ua(-kPi, kPi),
      u01(0, 1);
  int id = 1000000;
  for (int k = 0; k < 40; ++k) {
    const double a = ua(rng);
    m.obstacles.push_back(generated_stairs(id++, {ux(rng), uy(rng)}, {std::cos(a), std::sin(a)},
                                           3 + static_cast<int>(rng() % 5), 0.1 + 0.15 * u01(rng), 2 + 4 * u01(rng)));
  }
  for (int k = 0; k < 40; ++k) {
    const double a = ua(rng);
    m.obstacles.push_back(generated_ramp(id++, {ux(rng), uy(rng)}, {std::cos(a), std::sin(a)}, 3 + 5 * u01(rng),
                                         2 + 3 * u01(rng), 0.05 + 0.2 * u01(rng)));
  }
  return m;
}

struct Report {
  int rays = 0, hits = 0, mismatches = 0;
  int decided_by_special = 0;  // single rays whose range changes without stairs and ramps
  double worst = 0;
};

// The map without its stairs and ramps.
Map without_specials(Map m) {
  std::erase_if(m.obstacles,
                [](const Obstacle& o) { return o.type == ShapeType::Stairs || o.type == ShapeType::Ramp; });
  return m;
}

using Factory = std::function<std::unique_ptr<RayCaster>(const Map&, RayCasterOptions)>;
struct Candidate {
  std::string name;
  Factory make;
};

Candidate fast() {
  return {"fast", [](const Map& m, RayCasterOptions o) { return make_fast_ray_caster(m, o); }};
}
Candidate sweep(double cell) {
  return {"sweep " + std::to_string(cell).substr(0, 4) + " m", [cell](const Map& m, RayCasterOptions o) {
            return std::make_unique<SweepRayCaster>(m, o, SweepOptions{cell});
          }};
}
Candidate sweep(const std::string& name, SweepOptions o) {
  return {name, [o](const Map& m, RayCasterOptions opt) { return std::make_unique<SweepRayCaster>(m, opt, o); }};
}
SweepOptions sweep_options(double cell, size_t occluders, SweepKernel kernel) {
  SweepOptions o{cell};
  o.occluders = occluders;
  o.kernel = kernel;
  return o;
}
Candidate grid(double cell, bool skip) {
  return {"grid " + std::to_string(cell).substr(0, 4) + " m" + (skip ? "" : " no skip"),
          [cell, skip](const Map& m, RayCasterOptions o) {
            return std::make_unique<GridRayCaster>(m, o, GridOptions{cell, skip});
          }};
}

// Random rays (single, then in scans of 131 beams over 180 degrees) through the seed's
// caster and each candidate; every candidate must match the seed within kTolerance.
void expect_equivalent(const std::string& name, const Map& m, double laser_height,
                       const std::vector<Candidate>& candidates, int rays, double min_hit_share) {
  const RayCasterOptions opt{laser_height, 15.0};
  const SeedRayCaster seed(m, opt);
  const auto plain = make_fast_ray_caster(without_specials(m), opt);
  std::vector<std::unique_ptr<RayCaster>> casters;
  for (const Candidate& c : candidates) casters.push_back(c.make(m, opt));
  std::vector<Report> reps(casters.size());

  const Rect r = m.border.rect();
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> ux(r.xmin, r.xmax), uy(r.ymin, r.ymax), ua(-kPi, kPi);
  auto check = [&](size_t k, Point o, double angle, double want, double got) {
    Report& rep = reps[k];
    ++rep.rays;
    if (got < opt.rmax) ++rep.hits;
    const double diff = std::fabs(want - got);
    rep.worst = std::max(rep.worst, diff);
    if (!(diff <= kTolerance) && ++rep.mismatches <= 5)
      ADD_FAILURE() << name << " hL " << laser_height << ", " << candidates[k].name << ": origin (" << o.x << ", "
                    << o.y << ") angle " << angle << ": seed " << want << ", got " << got;
  };
  for (int i = 0; i < rays; ++i) {
    const Point o{ux(rng), uy(rng)};
    const double a = ua(rng);
    const double want = seed.cast(o, a);
    const double without = plain->cast(o, a);
    for (size_t k = 0; k < casters.size(); ++k) {
      const double got = casters[k]->cast(o, a);
      check(k, o, a, want, got);
      if (without != got) ++reps[k].decided_by_special;
    }
  }
  const std::vector<double> rel = evenly_spread_angles(131, kPi);
  std::vector<double> want(rel.size()), got(rel.size());
  for (int i = 0; i < kScans; ++i) {
    const Point o{ux(rng), uy(rng)};
    const double theta = ua(rng);
    seed.cast_scan(o, theta, rel, want.data());
    for (size_t k = 0; k < casters.size(); ++k) {
      casters[k]->cast_scan(o, theta, rel, got.data());
      for (size_t j = 0; j < rel.size(); ++j) check(k, o, theta + rel[j], want[j], got[j]);
    }
  }
  for (size_t k = 0; k < casters.size(); ++k) {
    const Report& rep = reps[k];
    const double share = static_cast<double>(rep.hits) / rep.rays;
    std::printf("  %-19s hL %.1f %-15s: %d rays, %d hit (%.1f %%), %d by stairs/ramps, worst diff %.3g m\n",
                name.c_str(), laser_height, candidates[k].name.c_str(), rep.rays, rep.hits, 100 * share,
                rep.decided_by_special, rep.worst);
    EXPECT_EQ(rep.mismatches, 0) << name << " hL " << laser_height << " " << candidates[k].name;
    EXPECT_GE(share, min_hit_share) << name << " hL " << laser_height << ": too few rays hit to compare";
  }
}

const Map& campus() {
  static const Map m = read_amrl_file(kMaps + "/UT_Campus.vectormap.txt", AmrlOptions{});
  return m;
}
const Map& gdc1() {
  static const Map m = read_amrl_file(kMaps + "/GDC1.vectormap.txt", AmrlOptions{});
  return m;
}

TEST(RayCasterEquivalence, RealMapsAsImported) {
  expect_equivalent("UT_Campus", campus(), 0.3, {fast(), grid(1, true)}, kRays, 0.1);
  expect_equivalent("GDC1", gdc1(), 0.3, {fast(), grid(1, true)}, kRays, 0.5);
}

TEST(RayCasterEquivalence, RealMapsWithHeightsStairsAndRamps) {
  const Map c = varied(campus(), 1), g = varied(gdc1(), 2);
  for (double hl : {0.1, 0.3, 1.0, 3.0}) {
    expect_equivalent("UT_Campus (varied)", c, hl, {fast(), grid(1, true)}, kRays, 0.03);
    expect_equivalent("GDC1 (varied)", g, hl, {fast(), grid(1, true)}, kRays, 0.2);
  }
}

TEST(RayCasterEquivalence, ExampleMap) {
  const Map m = read_seed_file(kExample);
  for (double hl : {0.1, 0.3, 1.0, 3.0})
    expect_equivalent("example-campus", m, hl, {fast(), grid(1, true)}, kRays, 0.2);
  // A window cuts the stairs and the ramp (SPEC 5.4): open outlines, a lost closing.
  const Map w = clip_map(m, window_rect(m.border, {28, 15}, 38, 12));
  for (double hl : {0.1, 0.3}) expect_equivalent("example window", w, hl, {fast(), grid(1, true)}, kRays, 0.1);
}

TEST(RayCasterEquivalence, OtherCellSizes) {
  const std::vector<Candidate> others = {grid(1, false), grid(0.25, true), grid(4, true), sweep(0.25), sweep(4)};
  expect_equivalent("UT_Campus (varied)", varied(campus(), 3), 0.3, others, kRays / 5, 0.03);
  expect_equivalent("example-campus", read_seed_file(kExample), 0.3, others, kRays / 5, 0.2);
}

// The dense floor, where occlusion culling drops the most walls, through each sweep
// kernel with and without culling and with fewer or more occluders tried (cells of 4 m
// built directly; 2, 1 and 0.5 m halved from them, level by level; fast() is 0.5 m).
TEST(RayCasterEquivalence, SweepKernelsAndCulling) {
  const std::vector<Candidate> sweeps = {
      sweep("per beam 2 m, 32", sweep_options(2, 32, SweepKernel::per_beam)),
      sweep("batched 4 m, no cull", sweep_options(4, 0, SweepKernel::batched)),
      sweep("batched 4 m, 8", sweep_options(4, 8, SweepKernel::batched)),
      sweep("batched 2 m, 64", sweep_options(2, 64, SweepKernel::batched)),
      sweep("batched 1 m, 32", sweep_options(1, 32, SweepKernel::batched)),
      sweep("batched 0.5 m, 8", sweep_options(0.5, 8, SweepKernel::batched)), fast()};
  expect_equivalent("GDC1 (varied)", varied(gdc1(), 4), 0.3, sweeps, kRays / 10, 0.2);
}

// Scans of other beam sets than 131 over 180 degrees, through the batched sweep: every
// direction (the scan's arc is the whole circle), more beams than the beam order's table
// has bins for one each (sweep_batched then finds runs through for_runs_between()), and a
// narrow fan, and beams not given by angle (the ranges are then put back one by one, not
// copied as a rotation of the beam order). On the dense floor with stairs and ramps, and
// on the campus.
TEST(RayCasterEquivalence, OtherBeamSets) {
  struct BeamSet {
    int beams;
    double fov;
    bool shuffled = false;
  };
  const BeamSet sets[] = {{360, 2 * kPi}, {2001, 0.5 * kPi}, {1081, 1.5 * kPi}, {7, 0.2}, {131, kPi, true}};
  const RayCasterOptions opt{0.3, 15.0};
  for (const Map& m : {varied(gdc1(), 5), campus()}) {
    const SeedRayCaster seed(m, opt);
    const SweepRayCaster fast(m, opt);
    const Rect r = m.border.rect();
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> ux(r.xmin, r.xmax), uy(r.ymin, r.ymax), ua(-kPi, kPi);
    for (const BeamSet& set : sets) {
      std::vector<double> rel = evenly_spread_angles(set.beams, set.fov);
      if (set.shuffled) std::shuffle(rel.begin(), rel.end(), rng);
      // Each path of sweep_batched is taken.
      EXPECT_EQ(beam_order(rel).one_per_bin, set.beams != 2001) << set.beams;
      EXPECT_EQ(beam_order(rel).rotated, !set.shuffled) << set.beams;
      std::vector<double> want(rel.size()), got(rel.size());
      int mismatches = 0, hits = 0, rays = 0;
      for (int i = 0; i < 40; ++i) {
        const Point o{ux(rng), uy(rng)};
        const double theta = ua(rng);
        seed.cast_scan(o, theta, rel, want.data());
        fast.cast_scan(o, theta, rel, got.data());
        for (size_t j = 0; j < rel.size(); ++j) {
          ++rays;
          hits += got[j] < opt.rmax;
          if (!(std::fabs(want[j] - got[j]) <= kTolerance) && ++mismatches <= 5)
            ADD_FAILURE() << set.beams << " beams over " << set.fov << " rad: origin (" << o.x << ", " << o.y
                          << ") angle " << theta + rel[j] << ": seed " << want[j] << ", got " << got[j];
        }
      }
      EXPECT_EQ(mismatches, 0) << set.beams << " beams over " << set.fov << " rad";
      EXPECT_GT(hits, rays / 20) << set.beams << " beams: too few rays hit to compare";
    }
  }
}

}  // namespace
}  // namespace fleetmap
