// Per-robot maps (common/slicing/map_slice.h): hand-computed slices of the example map, and the
// property that defines a slice: a ray caster at hL sees the same ranges on the slice at
// hL as on the whole map (random rays on the real maps and the example map).
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "common/io/amrl_import.h"
#include "common/slicing/map_slice.h"
#include "common/map/map_validation.h"
#include "common/map/ramp.h"
#include "common/io/seed_format.h"
#include "common/raycast/seed_ray_caster.h"

namespace fleetmap {
namespace {

constexpr double kPi = 3.14159265358979323846;
const std::string kExample = FLEETMAP_SOURCE_DIR "/maps/example-campus.map";
const std::string kMaps = FLEETMAP_REAL_MAPS;

const Map& example() {
  static const Map m = read_seed_file(kExample);
  return m;
}

const Obstacle* find(const Map& m, int id) {
  for (const Obstacle& o : m.obstacles)
    if (o.id == id) return &o;
  return nullptr;
}

std::vector<double> heights(const Obstacle& o) {
  std::vector<double> h;
  for (const Segment& s : o.segments) h.push_back(s.h);
  return h;
}

double cast(const Map& m, double hl, Point o, double angle, double rmax = 30) {
  return SeedRayCaster(m, {hl, rmax}).cast(o, angle);
}

// ---- hand-computed slices of maps/example-campus.map --------------------------------

TEST(MapSlice, ExampleAt30cm) {
  const Map s = slice_at_height(example(), 0.3);
  EXPECT_EQ(s.border, example().border);
  ASSERT_EQ(s.obstacles.size(), 7u);
  // Walls of 12, 9, 1.8, 0.8 and 0.45 m all stop a laser at 0.3 m: unchanged.
  for (int id : {1, 2, 3, 4, 5}) EXPECT_EQ(*find(s, id), *find(example(), id)) << id;
  // Stairs: steps of 0.45, 0.6 and 0.75 m (higher than the laser), and the closing segment.
  const Obstacle& st = *find(s, 6);
  EXPECT_EQ(st.type, ShapeType::Stairs);
  EXPECT_EQ(heights(st), (std::vector<double>{0.45, 0.6, 0.75, 0}));
  EXPECT_EQ(st.segments.front().a, (Point{44, 19.1}));
  // Ramp z = 0.125 (x - 8) reaches 0.3 m at x = 10.4: the walls of [10.4, 12] x [10, 12],
  // counter-clockwise as the ramp, h the highest surface height along each wall.
  const Obstacle& r = *find(s, 7);
  EXPECT_EQ(r.type, ShapeType::ClosedPolygon);
  EXPECT_EQ(r.semantic, "ramp,concrete,normal=-0.125:0:1,foot=8:10");
  ASSERT_EQ(r.segments.size(), 4u);
  const Point want[4][2] = {{{10.4, 10}, {12, 10}}, {{12, 10}, {12, 12}}, {{12, 12}, {10.4, 12}}, {{10.4, 12}, {10.4, 10}}};
  const double want_h[4] = {0.5, 0.5, 0.5, 0.3};
  for (int k = 0; k < 4; ++k) {
    EXPECT_NEAR(r.segments[k].a.x, want[k][0].x, 1e-12) << k;
    EXPECT_NEAR(r.segments[k].a.y, want[k][0].y, 1e-12) << k;
    EXPECT_NEAR(r.segments[k].b.x, want[k][1].x, 1e-12) << k;
    EXPECT_NEAR(r.segments[k].b.y, want[k][1].y, 1e-12) << k;
    EXPECT_NEAR(r.segments[k].h, want_h[k], 1e-12) << k;
  }
  EXPECT_EQ(r.segments[0].semantic, "edge,concrete");
  EXPECT_EQ(r.segments[3].semantic, "ramp-crossing");
  // Nothing was cut open at this height: even the whole-map rules hold.
  EXPECT_NO_THROW(validate_map(s, MapKind::Whole));
}

TEST(MapSlice, ExampleAtHigherLasers) {
  // 0.5 m: the bench (0.45) goes, two steps stay, the ramp is only its top edge x = 12
  // (the surface is at 0.5 m there): an open polygon, the edge and back.
  Map s = slice_at_height(example(), 0.5);
  EXPECT_EQ(find(s, 5), nullptr);
  EXPECT_EQ(heights(*find(s, 6)), (std::vector<double>{0.6, 0.75, 0}));
  const Obstacle& r = *find(s, 7);
  EXPECT_EQ(r.type, ShapeType::OpenPolygon);
  ASSERT_EQ(r.segments.size(), 2u);
  EXPECT_EQ(r.segments[0].a, (Point{12, 10}));
  EXPECT_EQ(r.segments[0].b, (Point{12, 12}));
  EXPECT_EQ(r.segments[1].a, (Point{12, 12}));
  EXPECT_EQ(r.segments[1].b, (Point{12, 10}));
  // 0.8 m: the fountain (0.8) still stops it, stairs (top step 0.75) and ramp are gone.
  s = slice_at_height(example(), 0.8);
  EXPECT_NE(find(s, 4), nullptr);
  EXPECT_EQ(find(s, 6), nullptr);
  EXPECT_EQ(find(s, 7), nullptr);
  // 2 m: the fence (1.8) goes; the library keeps its 2.5 m door.
  s = slice_at_height(example(), 2);
  EXPECT_EQ(find(s, 3), nullptr);
  EXPECT_EQ(find(s, 1)->segments.size(), 6u);
  // 3 m: the door goes, the library is an open chain of five walls (window rules).
  s = slice_at_height(example(), 3);
  EXPECT_EQ(find(s, 1)->segments.size(), 5u);
  EXPECT_THROW(validate_map(s, MapKind::Whole), std::invalid_argument);
  EXPECT_NO_THROW(validate_map(s, MapKind::Window));
  // 13 m: nothing is that high; the border stays.
  s = slice_at_height(example(), 13);
  EXPECT_TRUE(s.obstacles.empty());
  EXPECT_EQ(s.border, example().border);
}

TEST(MapSlice, AtFloorLevelTheRampIsItsWholeOutline) {
  const Map s = slice_at_height(example(), 0);
  const Obstacle& r = *find(s, 7);
  EXPECT_EQ(r.type, ShapeType::ClosedPolygon);
  ASSERT_EQ(r.segments.size(), 4u);
  EXPECT_EQ(r.segments[0].a, (Point{8, 10}));
  EXPECT_EQ(heights(r), (std::vector<double>{0.5, 0.5, 0.5, 0}));  // foot edge x = 8 at 0 m
}

TEST(MapSlice, RoundTripsThroughTheSeedFormat) {
  for (double hl : {0.0, 0.3, 0.5, 3.0}) {
    const Map s = slice_at_height(example(), hl);
    EXPECT_EQ(read_seed(write_seed(s), "slice", MapKind::Window), s) << hl;
  }
}

TEST(MapSlice, RefusesBadHeights) {
  EXPECT_THROW(slice_at_height(example(), -0.1), std::invalid_argument);
  EXPECT_THROW(slice_at_height(example(), NAN), std::invalid_argument);
}

// Hand-computed rays, each on the whole map and on the slice.
TEST(MapSlice, HandComputedRays) {
  const Map s = slice_at_height(example(), 0.3);
  struct Ray {
    Point o;
    double angle, range;
  } rays[] = {
      {{47, 17}, kPi / 2, 2.1},   // from below: the first step over 0.3 m (0.45 m at y = 19.1)
      {{47, 21}, -kPi / 2, 19},   // from the top landing: over the stairs down to the fence at y = 2
      {{5, 11}, 0, 5.4},          // up the ramp: the surface reaches 0.3 m at x = 10.4
      {{15, 11}, kPi, 3},         // onto the ramp's high side (0.5 m) at x = 12
      {{30, 10}, kPi / 2, 4},     // the bench (0.45 m) at (30, 14)
  };
  for (const Ray& r : rays) {
    EXPECT_NEAR(cast(example(), 0.3, r.o, r.angle), r.range, 1e-9) << r.o.x << "," << r.o.y;
    EXPECT_NEAR(cast(s, 0.3, r.o, r.angle), r.range, 1e-9) << r.o.x << "," << r.o.y;
  }
  // At 0.5 m the bench is gone from the slice and the ray reaches the fountain at y = 16.
  EXPECT_NEAR(cast(slice_at_height(example(), 0.5), 0.5, {30, 10}, kPi / 2), 6, 1e-9);
}

// A U-shaped ramp rising along +y: at 0.2 m only the tops of its two arms are high enough,
// two pieces, so one ST 2 obstacle holding two closed rings.
Map u_ramp_map() {
  Map m;
  m.border = {-5, 10, 11, -5};
  Obstacle r{1, ShapeType::Ramp, "ramp,u," + ramp_tokens(0, -0.1, 1, {0, 0}), {}, {}};
  const Point p[8] = {{0, 0}, {6, 0}, {6, 4}, {4, 4}, {4, 1}, {2, 1}, {2, 4}, {0, 4}};
  for (int k = 0; k < 8; ++k) r.segments.push_back({p[k], p[(k + 1) % 8], 0, 0, "edge", ""});
  m.obstacles.push_back(r);
  return m;
}

TEST(MapSlice, ConcaveRampFallsApart) {
  const Map s = slice_at_height(u_ramp_map(), 0.2);
  const Obstacle& r = s.obstacles.at(0);
  EXPECT_EQ(r.type, ShapeType::OpenPolygon);
  ASSERT_EQ(r.segments.size(), 8u);  // two rectangles [0,2] x [2,4] and [4,6] x [2,4]
  double len = 0;
  for (const Segment& g : r.segments) {
    len += g.length();
    EXPECT_GE(g.a.y, 2 - 1e-12);
  }
  EXPECT_NEAR(len, 16, 1e-9);
  EXPECT_NO_THROW(validate_map(s, MapKind::Window));
  // From inside the U's notch: the arm's inner side is 0.3 m high at y = 3, 0.15 m at y = 1.5.
  EXPECT_NEAR(cast(s, 0.2, {3, 3}, 0), 1, 1e-9);
  EXPECT_NEAR(cast(u_ramp_map(), 0.2, {3, 3}, 0), 1, 1e-9);
  EXPECT_EQ(cast(s, 0.2, {3, 1.5}, 0), 30);
  EXPECT_EQ(cast(u_ramp_map(), 0.2, {3, 1.5}, 0), 30);
}

// ---- the defining property, on random rays --------------------------------------------

Obstacle stairs(int id, Point base, Point u, int n, double rise, double w) {
  const Point v{-u.y, u.x};
  Obstacle o{id, ShapeType::Stairs, "stairs", {}, {}};
  for (int k = 0; k <= n; ++k) {
    const Point mid = base + (0.3 * k) * u, l = mid + (w / 2) * v, r = mid + (-w / 2) * v;
    if (k < n) o.segments.push_back({r, l, rise * (k + 1), 1, "step", ""});
    else o.segments.push_back({l, r, 0, 1, "step", ""});
  }
  return o;
}

Obstacle ramp(int id, Point foot, Point u, double len, double w, double slope) {
  const Point v{-u.y, u.x};
  const Point p[4] = {foot + (-w / 2) * v, foot + (-w / 2) * v + len * u, foot + (w / 2) * v + len * u,
                      foot + (w / 2) * v};
  Obstacle o{id, ShapeType::Ramp, "ramp," + ramp_tokens(-slope * u.x, -slope * u.y, 1, foot), {}, {}};
  for (int k = 0; k < 4; ++k) o.segments.push_back({p[k], p[(k + 1) % 4], 0, 1, "edge", ""});
  return o;
}

// Wall heights from {0.2, 0.6, 2, 4} m, 30 stairs and 30 ramps at random places.
Map varied(Map m, unsigned seed) {
  std::mt19937_64 rng(seed);
  const double hs[] = {0.2, 0.6, 2.0, 4.0};
  for (Obstacle& o : m.obstacles)
    for (Segment& s : o.segments) s.h = hs[rng() % 4];
  const Rect r = m.border.rect();
  std::uniform_real_distribution<double> ux(r.xmin + 10, r.xmax - 10), uy(r.ymin + 10, r.ymax - 10), ua(-kPi, kPi),
      u01(0, 1);
  int id = 1000000;
  for (int k = 0; k < 30; ++k) {
    const double a = ua(rng);
    m.obstacles.push_back(stairs(id++, {ux(rng), uy(rng)}, {std::cos(a), std::sin(a)}, 3 + rng() % 5,
                                 0.1 + 0.15 * u01(rng), 2 + 4 * u01(rng)));
  }
  for (int k = 0; k < 30; ++k) {
    const double a = ua(rng);
    m.obstacles.push_back(ramp(id++, {ux(rng), uy(rng)}, {std::cos(a), std::sin(a)}, 3 + 5 * u01(rng),
                               2 + 3 * u01(rng), 0.05 + 0.2 * u01(rng)));
  }
  for (Obstacle& o : m.obstacles) o.compute_bound();
  return m;
}

// Rays from inside a ramp's polygon are a robot on the ramp: never stopped by it on the
// whole map (ray_rules.h), a 2D slice cannot say so. They are not compared.
bool on_a_ramp(const Map& m, Point p) {
  for (const Obstacle& o : m.obstacles)
    if (o.type == ShapeType::Ramp && RampRule(o, 0).contains(p)) return true;
  return false;
}

// Ranges on the slice at hL equal those on the whole map: bit for bit where no ramp
// decides (the slice holds the very same segments and stairs rule), within 1e-6 m where
// a ramp does. The ramp's stop is computed two ways, t = enter + (hL - z) / slope along
// the ray and a ray against the crossing segment; both are exact up to rounding of
// ~1e-13 m on these coordinates (< 1 km), amplified by 1 / sin of the angle between the
// ray and the crossing line, so 1e-6 m fails only for rays within ~1e-7 rad of it.
void expect_same_ranges(const std::string& name, const Map& m, double hl, int rays, unsigned seed) {
  const Map s = slice_at_height(m, hl);
  ASSERT_NO_THROW(validate_map(s, MapKind::Window)) << name;
  const RayCasterOptions opt{hl, 15.0};
  const SeedRayCaster whole(m, opt), sliced(s, opt);
  Map no_ramps = m;
  std::erase_if(no_ramps.obstacles, [](const Obstacle& o) { return o.type == ShapeType::Ramp; });
  const SeedRayCaster without(no_ramps, opt);
  const Rect r = m.border.rect();
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> ux(r.xmin, r.xmax), uy(r.ymin, r.ymax), ua(-kPi, kPi);
  int compared = 0, hits = 0, by_ramp = 0, failures = 0;
  double worst = 0;
  while (compared < rays) {
    const Point o{ux(rng), uy(rng)};
    if (on_a_ramp(m, o)) continue;
    const double a = ua(rng);
    const double want = whole.cast(o, a), got = sliced.cast(o, a);
    const bool ramp_decides = without.cast(o, a) != want;
    ++compared;
    hits += want < opt.rmax;
    by_ramp += ramp_decides;
    const double diff = std::fabs(want - got);
    worst = std::max(worst, diff);
    const bool ok = ramp_decides ? diff <= 1e-6 : want == got;
    if (!ok && ++failures <= 5)
      ADD_FAILURE() << name << " hL " << hl << ": origin (" << o.x << ", " << o.y << ") angle " << a << ": whole "
                    << want << ", slice " << got;
  }
  std::printf("  %-10s hL %-5g: %d rays, %d hit, %d decided by a ramp, worst diff %.3g m\n", name.c_str(), hl,
              compared, hits, by_ramp, worst);
  EXPECT_EQ(failures, 0) << name << " hL " << hl;
  EXPECT_GT(hits, rays / 50) << name << " hL " << hl << ": too few hits to compare";
}

// Not at 0.5 m, the ramp's top: there R is the top edge alone, and whether a ray through
// the ramp meets it is decided by rounding in RampRule (z = 0.49999999999999994 or 0.5 at
// x = 12), while the slice's wall at exactly hL always stops it (stops_laser: h >= hL).
TEST(MapSlice, SameRangesOnTheExampleMap) {
  for (double hl : {0.0, 0.1, 0.3, 0.44, 0.499, 0.501, 0.7, 1.0, 2.0})
    expect_same_ranges("example", example(), hl, 20000, 7);
}

TEST(MapSlice, SameRangesOnAConcaveRamp) {
  for (double hl : {0.05, 0.2, 0.35}) expect_same_ranges("U ramp", u_ramp_map(), hl, 5000, 3);
}

TEST(MapSlice, SameRangesOnTheRealMaps) {
  const Map gdc1 = read_amrl_file(kMaps + "/GDC1.vectormap.txt", AmrlOptions{});
  const Map campus = read_amrl_file(kMaps + "/UT_Campus.vectormap.txt", AmrlOptions{});
  expect_same_ranges("GDC1", gdc1, 0.3, 20000, 1);  // as imported: 2 m walls
  const Map g = varied(gdc1, 11), c = varied(campus, 12);
  for (double hl : {0.15, 0.4, 1.0, 3.0}) {
    expect_same_ranges("GDC1*", g, hl, 20000, 2);
    expect_same_ranges("campus*", c, hl, 20000, 3);
  }
}

}  // namespace
}  // namespace fleetmap
