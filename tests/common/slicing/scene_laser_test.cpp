// common/slicing/scene_laser.*: what a laser at height hL sees of the semantic layer
// (seed 004 section III.A). Rays through 2.5D and 3D objects at several heights, with
// ranges computed by hand, through the seed's ray caster and the fast one; then the
// example room (maps/example-room.*), its seed map read by the existing reader.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <functional>
#include <memory>
#include <sstream>

#include "common/io/scene_geojson.h"
#include "common/slicing/scene_laser.h"
#include "common/io/seed_format.h"
#include "common/raycast/seed_ray_caster.h"
#include "common/raycast/sweep_ray_caster.h"

namespace fleetmap {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kEps = 1e-9;

Polygon rect(double x0, double y0, double x1, double y1) { return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}; }

// A wall block at x 10..11, y -5..5, 2.5 m high: rays that pass everything end at 10.
Map walled_map() {
  Map m;
  m.border = {-20, 20, 20, -20};
  Obstacle wall{7, ShapeType::ClosedPolygon, "wall", {}, {}};
  const Polygon r = rect(10, -5, 11, 5);
  for (size_t i = 0; i < 4; ++i) wall.segments.push_back({r[i], r[(i + 1) % 4], 2.5, 0, "wall", ""});
  wall.compute_bound();
  m.obstacles = {wall};
  return m;
}

// t1: a table, four 6 cm legs 0..0.72 (two of them on the x axis: x 1.85..1.91 and
//     2.89..2.95) and a top 0.72..0.76 over x 1.8..3.0, y -0.5..1.
// b1: a 2.5D box 0..0.5 over x 4..5, y 2.5..3.5 (written clockwise).
// p1: a 2D plant over x 6..7, y -3.5..-2.5: blocks at every height.
// s1: a shelf board 1.1..1.12 over x 3..4, y -1.7..-1.3.
Scene test_scene() {
  Scene s;
  EnvObject table{"t1", "table", {}, false};
  for (double x : {1.85, 2.89})
    for (double y : {-0.03, 0.91}) table.elements.push_back({rect(x, y, x + 0.06, y + 0.06), HeightRange{0, 0.72}});
  table.elements.push_back({rect(1.8, -0.5, 3.0, 1.0), HeightRange{0.72, 0.76}});
  Polygon cw = rect(4, 2.5, 5, 3.5);
  std::reverse(cw.begin(), cw.end());
  s.objects = {table,
               {"b1", "box", {{cw, HeightRange{0, 0.5}}}, false},
               {"p1", "plant", {{rect(6, -3.5, 7, -2.5), std::nullopt}}, false},
               {"s1", "shelf", {{rect(3, -1.7, 4, -1.3), HeightRange{1.1, 1.12}}}, false}};
  return s;
}

using Factory = std::function<std::unique_ptr<RayCaster>(const Map&, RayCasterOptions)>;
const std::vector<std::pair<std::string, Factory>> kCasters = {
    {"seed", [](const Map& m, RayCasterOptions o) { return std::make_unique<SeedRayCaster>(m, o); }},
    {"fast", [](const Map& m, RayCasterOptions o) { return make_fast_ray_caster(m, o); }},
};

double cast_at(const Map& map, const Scene& scene, double h, Point o, double angle, const Factory& make) {
  const Map seen = with_objects_at_height(map, scene, h);
  const auto caster = make(seen, {h, 15.0});
  return caster->cast(o, angle);
}

struct Ray {
  double h;
  Point origin;
  double angle;
  double expected;
  const char* why;
};

TEST(SceneLaser, HandComputedRaysThroughObjects) {
  const Map map = walled_map();
  const Scene scene = test_scene();
  const std::vector<Ray> rays = {
      {0.38, {0, 0}, 0, 1.85, "the near leg, under the top"},
      {0.38, {5, 0}, kPi, 5 - 2.95, "the far leg, from the other side"},
      {0.72, {0, 0}, 0, 1.8, "top and legs both contain 0.72: the top's edge is nearer"},
      {0.74, {0, 0}, 0, 1.8, "the top's edge"},
      {0.74, {5, 0}, kPi, 2.0, "the top's edge from the other side"},
      {0.76, {0, 0}, 0, 1.8, "zmax belongs to the range"},
      {0.7601, {0, 0}, 0, 10, "over the table: the wall"},
      {0.9, {0, 0}, 0, 10, "over the table: the wall"},
      {0.38, {0, 0.5}, 0, 10, "between the legs, under the top"},
      {0.38, {0, 3}, 0, 4, "the 2.5D box"},
      {0.5, {0, 3}, 0, 4, "the box's top height"},
      {0.6, {0, 3}, 0, 10, "over the box"},
      {0.1, {0, -3}, 0, 6, "the 2D plant"},
      {3.0, {0, -3}, 0, 6, "the 2D plant over the wall's height"},
      {3.0, {0, 0}, 0, 15, "over the 2.5 m wall: rmax"},
      {0.38, {0, -1.5}, 0, 10, "under the shelf board"},
      {1.11, {0, -1.5}, 0, 3, "the shelf board"},
      {1.2, {0, -1.5}, 0, 10, "over the shelf board"},
      {0.3, {3.5, 3}, kPi / 2, 15, "nothing north of the box"},
      {0.3, {4.5, 6}, -kPi / 2, 6 - 3.5, "the box from the north"},
  };
  for (const auto& [name, make] : kCasters)
    for (const Ray& r : rays)
      EXPECT_NEAR(cast_at(map, scene, r.h, r.origin, r.angle, make), r.expected, kEps)
          << name << " hL " << r.h << ": " << r.why;
}

TEST(SceneLaser, ObstaclesAdded) {
  const Map map = walled_map();
  const Map low = with_objects_at_height(map, test_scene(), 0.38);
  // The wall, 4 legs, the box, the plant; not the top nor the board.
  ASSERT_EQ(low.obstacles.size(), 7u);
  EXPECT_EQ(low.obstacles[0], map.obstacles[0]);
  for (size_t i = 1; i < 7; ++i) {
    const Obstacle& o = low.obstacles[i];
    EXPECT_EQ(o.id, static_cast<int>(7 + i)) << "after the map's largest id";
    EXPECT_EQ(o.type, ShapeType::ClosedPolygon);
    ASSERT_EQ(o.segments.size(), 4u);
    double twice_area = 0;
    for (size_t k = 0; k < 4; ++k) {
      EXPECT_EQ(o.segments[k].b, o.segments[(k + 1) % 4].a) << "a closed chain";
      twice_area += cross(o.segments[k].a, o.segments[k].b);
    }
    EXPECT_GT(twice_area, 0) << "counter-clockwise, the box too: " << o.semantic;
    EXPECT_GT(o.bound.r, 0) << "bounding circle computed";
  }
  EXPECT_EQ(low.obstacles[1].semantic, "object:table:t1");
  EXPECT_EQ(low.obstacles[1].segments[0].h, 0.72);
  EXPECT_EQ(low.obstacles[5].semantic, "object:box:b1");
  EXPECT_EQ(low.obstacles[5].segments[0].h, 0.5);
  EXPECT_EQ(low.obstacles[6].semantic, "object:plant:p1");
  EXPECT_EQ(low.obstacles[6].segments[0].h, kObjectWallHeight);
  EXPECT_NO_THROW(validate_map(low));

  const Map high = with_objects_at_height(map, test_scene(), 0.74);
  ASSERT_EQ(high.obstacles.size(), 3u);  // the wall, the top, the plant
  EXPECT_EQ(high.obstacles[1].semantic, "object:table:t1");
  EXPECT_EQ(high.obstacles[1].segments[0].h, 0.76);
  EXPECT_EQ(with_objects_at_height(map, Scene{}, 0.38), map);
}

// --- the example room ---------------------------------------------------------------

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(SceneLaser, ExampleRoomSeedMapIsValidAndCanonical) {
  const std::string path = FLEETMAP_SOURCE_DIR "/maps/example-room.map";
  const Map m = read_seed_file(path);  // validates
  EXPECT_EQ(m.obstacles.size(), 9u);    // 5 wall blocks, 4 columns
  EXPECT_EQ(m.border, (Border{-0.5, 15.5, 15.5, -0.5}));
  EXPECT_EQ(write_seed(m), slurp(path));
}

TEST(SceneLaser, ExampleRoomRays) {
  const Map map = read_seed_file(FLEETMAP_SOURCE_DIR "/maps/example-room.map");
  const Scene scene = read_scene_geojson(slurp(FLEETMAP_SOURCE_DIR "/maps/example-room.geojson"));
  const std::vector<Ray> rays = {
      // North from (7.5, 3): between the chairs, under the big table's top (y 7..8).
      {0.38, {7.5, 3}, kPi / 2, 12, "between legs and chairs to the north wall"},
      {0.74, {7.5, 3}, kPi / 2, 4, "the big table's top"},
      {0.9, {7.5, 3}, kPi / 2, 12, "over the top, beside the backrests"},
      // South from (7.5, 3): the closed door (0..2.1 m) in the wall's opening.
      {0.38, {7.5, 3}, -kPi / 2, 3, "the door"},
      {2.0, {7.5, 3}, -kPi / 2, 3, "the door"},
      {2.2, {7.5, 3}, -kPi / 2, 15, "over the door, through the opening: rmax"},
      // East along y = 7.5: under the top between the legs (y 7.05..7.11, 7.89..7.95).
      {0.38, {3, 7.5}, 0, 12, "under the big table to the east wall"},
      {0.74, {3, 7.5}, 0, 3.5, "the big table's top"},
      // East along y = 6.44: chair-1's leg (0..0.43), seat (0.43..0.47), backrest (..0.9).
      {0.38, {3, 6.44}, 0, 3.775, "chair-1's front-left leg"},
      {0.45, {3, 6.44}, 0, 3.775, "chair-1's seat"},
      {0.8, {3, 6.44}, 0, 3.775, "chair-1's backrest"},
      {1.0, {3, 6.44}, 0, 12, "over the chairs"},
      // The 2D plant: its octagon's west edge at x = 13.269, any height.
      {0.2, {10, 13.5}, 0, 3.269, "the plant"},
      {2.4, {10, 13.5}, 0, 3.269, "the plant"},
  };
  for (const auto& [name, make] : kCasters)
    for (const Ray& r : rays)
      EXPECT_NEAR(cast_at(map, scene, r.h, r.origin, r.angle, make), r.expected, kEps)
          << name << " hL " << r.h << ": " << r.why;
}

}  // namespace
}  // namespace fleetmap
