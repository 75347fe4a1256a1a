// The scene's rules (common/scene/scene_validation.h): for each, a value that passes and
// one that breaks it, and the message names the field and what was expected.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "common/scene/scene_validation.h"

namespace fleetmap {
namespace {

const Polygon kSquare{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
const Polygon kBowTie{{0, 0}, {1, 1}, {1, 0}, {0, 1}};  // edges cross

// The message, or "" when valid; a test of a violation then fails on find().
std::string msg(const std::optional<std::string>& m) { return m.value_or(""); }

bool has(const std::optional<std::string>& m, const std::string& part) { return m && m->find(part) != std::string::npos; }

Scene valid_scene() {
  Scene s;
  s.bounds = Polygon{{-10, -10}, {10, -10}, {10, 10}, {-10, 10}};
  s.objects.push_back({"table-1", "table", {{kSquare, HeightRange{0, 0.75}}, {kSquare, std::nullopt}}, false});
  s.objects.push_back({"door-1", "door", {{kSquare, std::nullopt}}, false});
  s.avoided.push_back({"keepout", kSquare});
  return s;
}

TEST(SceneValidation, Tag) {
  EXPECT_EQ(check_tag("table"), std::nullopt);
  EXPECT_EQ(check_tag(std::string(64, 't')), std::nullopt);
  EXPECT_TRUE(has(check_tag(""), "expected a tag of 1-64 bytes")) << msg(check_tag(""));
  EXPECT_TRUE(has(check_tag(std::string(65, 't')), "expected a tag of 1-64 bytes"));
  EXPECT_TRUE(has(check_tag("a:b"), "expected a tag without ':', got 'a:b'")) << msg(check_tag("a:b"));
  // check_text's rules: the seed format's delimiters and control characters.
  EXPECT_TRUE(has(check_tag("a;b"), "a tag")) << msg(check_tag("a;b"));
  EXPECT_TRUE(has(check_tag("a\nb"), "a tag")) << msg(check_tag("a\nb"));
}

TEST(SceneValidation, TagClass) {
  for (const char* c : {"obstacle", "landmark", "interactable", "dynamic"}) EXPECT_EQ(check_tag_class(c), std::nullopt) << c;
  EXPECT_TRUE(has(check_tag_class("furniture"), "expected a tag class (obstacle, landmark, interactable or dynamic), got 'furniture'"));
  EXPECT_TRUE(has(check_tag_class("Obstacle"), "expected a tag class"));  // case matters
  EXPECT_TRUE(has(check_tag_class(""), "expected a tag class"));
}

TEST(SceneValidation, Description) {
  EXPECT_EQ(check_description(""), std::nullopt);
  EXPECT_EQ(check_description(std::string(255, 'd')), std::nullopt);
  EXPECT_TRUE(has(check_description(std::string(256, 'd')), "expected a description of at most 255 bytes, got 256"));
}

TEST(SceneValidation, Key) {
  EXPECT_EQ(check_key("k", "object"), std::nullopt);
  EXPECT_EQ(check_key(std::string(255, 'k'), "object"), std::nullopt);
  EXPECT_TRUE(has(check_key("", "object"), "expected object keys of 1-255 bytes"));
  EXPECT_TRUE(has(check_key(std::string(256, 'k'), "avoided-area"), "expected avoided-area keys of 1-255 bytes"));
}

TEST(SceneValidation, HeightRange) {
  EXPECT_EQ(check_height_range({0, 0.72}), std::nullopt);
  EXPECT_EQ(check_height_range({-1, 0}), std::nullopt);  // below the floor is the caller's business
  EXPECT_TRUE(has(check_height_range({0.76, 0.72}), "expected finite heights with zmin < zmax, got [0.76, 0.72]"));
  EXPECT_TRUE(has(check_height_range({0.5, 0.5}), "zmin < zmax"));
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  EXPECT_TRUE(has(check_height_range({nan, 1}), "expected finite heights"));
  EXPECT_TRUE(has(check_height_range({0, inf}), "expected finite heights"));
}

TEST(SceneValidation, Polygon) {
  EXPECT_EQ(check_polygon(kSquare, "bounds"), std::nullopt);
  EXPECT_TRUE(has(check_polygon(kBowTie, "bounds"), "bounds: ")) << msg(check_polygon(kBowTie, "bounds"));
  EXPECT_TRUE(has(check_polygon({{0, 0}, {1, 0}}, "avoided area 'a'"), "avoided area 'a': "));
}

TEST(SceneValidation, ValidSceneAndEmptySceneAreAccepted) {
  EXPECT_EQ(check_scene(valid_scene()), std::nullopt) << msg(check_scene(valid_scene()));
  EXPECT_EQ(check_scene(Scene{}), std::nullopt);
  EXPECT_NO_THROW(validate_scene(valid_scene()));
}

TEST(SceneValidation, ObjectKeyEmptyOrDuplicate) {
  Scene s = valid_scene();
  s.objects[1].id = "";
  EXPECT_TRUE(has(check_scene(s), "expected object keys of 1-255 bytes")) << msg(check_scene(s));
  s.objects[1].id = "table-1";
  EXPECT_TRUE(has(check_scene(s), "object key 'table-1' appears twice")) << msg(check_scene(s));
}

TEST(SceneValidation, ObjectTag) {
  Scene s = valid_scene();
  s.objects[1].tag = "door:left";
  EXPECT_TRUE(has(check_scene(s), "object 'door-1' tag: expected a tag without ':'")) << msg(check_scene(s));
}

TEST(SceneValidation, ObjectWithoutElements) {
  Scene s = valid_scene();
  s.objects[1].elements.clear();
  EXPECT_TRUE(has(check_scene(s), "object 'door-1': expected at least one element")) << msg(check_scene(s));
}

TEST(SceneValidation, ElementFootprint) {
  Scene s = valid_scene();
  s.objects[0].elements[1].footprint = kBowTie;
  EXPECT_TRUE(has(check_scene(s), "object 'table-1' element 1 footprint: ")) << msg(check_scene(s));
}

TEST(SceneValidation, ElementHeights) {
  Scene s = valid_scene();
  s.objects[0].elements[0].z = HeightRange{0.75, 0};
  EXPECT_TRUE(has(check_scene(s), "object 'table-1' element 0 z: expected finite heights with zmin < zmax"))
      << msg(check_scene(s));
}

TEST(SceneValidation, AvoidedAreas) {
  Scene s = valid_scene();
  s.avoided.push_back({"keepout", kSquare});
  EXPECT_TRUE(has(check_scene(s), "avoided area 'keepout' appears twice")) << msg(check_scene(s));
  s.avoided[1] = {"", kSquare};
  EXPECT_TRUE(has(check_scene(s), "expected avoided-area keys of 1-255 bytes")) << msg(check_scene(s));
  s.avoided[1] = {"zone", kBowTie};
  EXPECT_TRUE(has(check_scene(s), "avoided area 'zone': ")) << msg(check_scene(s));
  // An object and an avoided area may share a key: they are different kinds.
  s.avoided[1] = {"table-1", kSquare};
  EXPECT_EQ(check_scene(s), std::nullopt) << msg(check_scene(s));
}

TEST(SceneValidation, Bounds) {
  Scene s = valid_scene();
  s.bounds = kBowTie;
  EXPECT_TRUE(has(check_scene(s), "bounds: ")) << msg(check_scene(s));
  try {
    validate_scene(s);
    FAIL() << "bad bounds accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), msg(check_scene(s)));
  }
}

}  // namespace
}  // namespace fleetmap
