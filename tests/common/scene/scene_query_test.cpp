// common/scene/scene_query.*: nearest objects and avoided areas containing a point, by hand and
// against references written here (winding number, own point-segment distance) on
// 1 000 random points of the example room.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <random>
#include <sstream>

#include "common/io/scene_geojson.h"
#include "common/scene/scene_query.h"

namespace fleetmap {
namespace {

Polygon rect(double x0, double y0, double x1, double y1) { return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}; }

// b and a are unit boxes 1 m either side of (2, 0.5); chair c has a far leg and a near
// seat high up; chair d is far away.
Scene small_scene() {
  Scene s;
  s.objects = {{"b", "box", {{rect(3, 0, 4, 1), HeightRange{0, 0.5}}}, false},
               {"a", "box", {{rect(0, 0, 1, 1), std::nullopt}}, false},
               {"c", "chair", {{rect(10, 10, 11, 11), HeightRange{0, 0.4}}, {rect(2, 3, 3, 4), HeightRange{0.4, 0.45}}}, false},
               {"d", "chair", {{rect(20, 20, 21, 21), std::nullopt}}, false}};
  s.avoided = {{"z2", rect(0, 0, 2, 2)}, {"z1", rect(1, 1, 3, 3)}, {"tri", {{10, 0}, {12, 0}, {10, 2}}}};
  return s;
}

TEST(SceneQuery, NearestObjectsByHand) {
  const Scene s = small_scene();
  const Point p{2, 0.5};
  EXPECT_EQ(nearest_objects(s, p, "", 1), (std::vector<NearObject>{{"a", 1}}));  // a and b tie: by id
  const auto all = nearest_objects(s, p, "", 10);
  ASSERT_EQ(all.size(), 4u);
  EXPECT_EQ(all[0], (NearObject{"a", 1}));
  EXPECT_EQ(all[1], (NearObject{"b", 1}));
  EXPECT_EQ(all[2].id, "c");  // its seat, whatever its height: 2.5 m above p
  EXPECT_DOUBLE_EQ(all[2].distance, 2.5);
  EXPECT_EQ(all[3].id, "d");
  EXPECT_DOUBLE_EQ(all[3].distance, std::hypot(18, 19.5));
  EXPECT_EQ(nearest_objects(s, p, "chair", 5).size(), 2u);
  EXPECT_EQ(nearest_objects(s, p, "chair", 5)[0].id, "c");
  EXPECT_TRUE(nearest_objects(s, p, "sofa", 5).empty());
  EXPECT_TRUE(nearest_objects(s, p, "", 0).empty());
  EXPECT_TRUE(nearest_objects(s, p, "", -3).empty());
  // Inside or on the outline: 0.
  EXPECT_EQ(nearest_objects(s, {3.5, 0.5}, "", 1), (std::vector<NearObject>{{"b", 0}}));
  EXPECT_EQ(nearest_objects(s, {1, 0.25}, "box", 1), (std::vector<NearObject>{{"a", 0}}));
  EXPECT_DOUBLE_EQ(distance_to_object({12, 12}, s.objects[2]), std::sqrt(2.0));  // the far leg
}

TEST(SceneQuery, AvoidedAreasByHand) {
  const Scene s = small_scene();
  EXPECT_EQ(containing_avoided_areas(s, {1.5, 1.5}), (std::vector<std::string>{"z1", "z2"}));  // sorted
  EXPECT_EQ(containing_avoided_areas(s, {2, 2}), (std::vector<std::string>{"z1", "z2"}));      // both outlines
  EXPECT_EQ(containing_avoided_areas(s, {0.5, 0.5}), (std::vector<std::string>{"z2"}));
  EXPECT_EQ(containing_avoided_areas(s, {2.5, 2.5}), (std::vector<std::string>{"z1"}));
  EXPECT_EQ(containing_avoided_areas(s, {11, 1}), (std::vector<std::string>{"tri"}));  // on the hypotenuse
  EXPECT_TRUE(containing_avoided_areas(s, {11.01, 1}).empty());
  EXPECT_TRUE(containing_avoided_areas(s, {5, 5}).empty());
  EXPECT_TRUE(within_bounds(s, {1e6, 1e6}));  // no bounds: everywhere
  Scene b = s;
  b.bounds = rect(0, 0, 15, 15);
  EXPECT_TRUE(within_bounds(b, {15, 7}));
  EXPECT_FALSE(within_bounds(b, {15.001, 7}));
}

// --- references ---------------------------------------------------------------------

// Winding number of the ring around p (non-zero inside); points on the outline do not
// occur among random reals.
int winding(Point p, const Polygon& ring) {
  int w = 0;
  for (size_t i = 0; i < ring.size(); ++i) {
    const Point a = ring[i], b = ring[(i + 1) % ring.size()];
    const double side = (b.x - a.x) * (p.y - a.y) - (p.x - a.x) * (b.y - a.y);
    if (a.y <= p.y && b.y > p.y && side > 0) ++w;
    if (a.y > p.y && b.y <= p.y && side < 0) --w;
  }
  return w;
}

double ref_distance(Point p, const EnvObject& o) {
  double best = INFINITY;
  for (const Element& e : o.elements) {
    if (winding(p, e.footprint) != 0) return 0;
    for (size_t i = 0; i < e.footprint.size(); ++i) {
      const Point a = e.footprint[i], b = e.footprint[(i + 1) % e.footprint.size()];
      const double ex = b.x - a.x, ey = b.y - a.y;
      const double t = std::clamp(((p.x - a.x) * ex + (p.y - a.y) * ey) / (ex * ex + ey * ey), 0.0, 1.0);
      best = std::min(best, std::hypot(a.x + t * ex - p.x, a.y + t * ey - p.y));
    }
  }
  return best;
}

Scene example_room() {
  std::ifstream in(FLEETMAP_SOURCE_DIR "/maps/example-room.geojson");
  std::ostringstream s;
  s << in.rdbuf();
  return read_scene_geojson(s.str());
}

TEST(SceneQuery, ExampleRoomAgainstReferenceOnRandomPoints) {
  const Scene room = example_room();
  std::mt19937 rng(1234);
  std::uniform_real_distribution<double> u(-1, 16), near_table(6, 9);  // half of them among the chairs
  const std::vector<std::string> tags = {"", "chair", "table", "box", "plant"};
  int in_avoided = 0, in_object = 0;
  for (int n = 0; n < 1000; ++n) {
    const Point p = n % 2 ? Point{u(rng), u(rng)} : Point{near_table(rng), near_table(rng)};
    const std::string& tag = tags[n % tags.size()];
    const int k = 1 + n % 7;
    std::vector<NearObject> ref;
    for (const EnvObject& o : room.objects)
      if (tag.empty() || o.tag == tag) ref.push_back({o.id, ref_distance(p, o)});
    std::sort(ref.begin(), ref.end(), [](const NearObject& a, const NearObject& b) {
      return a.distance < b.distance || (a.distance == b.distance && a.id < b.id);
    });
    ref.resize(std::min(ref.size(), static_cast<size_t>(k)));
    const auto got = nearest_objects(room, p, tag, k);
    ASSERT_EQ(got.size(), ref.size()) << p.x << "," << p.y;
    for (size_t i = 0; i < ref.size(); ++i) {
      EXPECT_EQ(got[i].id, ref[i].id) << p.x << "," << p.y << " rank " << i;
      EXPECT_NEAR(got[i].distance, ref[i].distance, 1e-12);
    }
    if (!ref.empty() && ref[0].distance == 0) ++in_object;

    std::vector<std::string> areas;
    for (const AvoidedArea& a : room.avoided)
      if (winding(p, a.area) != 0) areas.push_back(a.id);
    std::sort(areas.begin(), areas.end());
    EXPECT_EQ(containing_avoided_areas(room, p), areas) << p.x << "," << p.y;
    in_avoided += !areas.empty();
  }
  // Both answers occur in the sample (walls, columns and the keep-out cover ~7%).
  EXPECT_GT(in_avoided, 15);
  EXPECT_GT(in_object, 20);
}

}  // namespace
}  // namespace fleetmap
