#include "common/gis/import_rules.h"

#include <gtest/gtest.h>

#include "common/core/error.h"

namespace fleetmap {
namespace {

TEST(ImportRules, ParsesAFileAsDocumented) {
  const ImportRules r = parse_import_rules(R"({
    "layers": ["buildings"], "margin": 5, "curve_step_degrees": 2,
    "rules": [
      {"key": "TYPE", "values": ["wall", "fence"], "action": "open", "in_out": 0,
       "height": {"attribute": "H", "levels_attribute": "FLOORS", "level_height": 4, "default": 2}},
      {"geometry": "point", "action": "object", "tag": "bollard", "object_size": 0.3, "object_height": 1},
      {"key": "ROOM", "action": "closed", "free_space": "inside", "name": "rooms"}
    ]})",
                                           "rules.json");
  ASSERT_EQ(r.rules.size(), 3u);
  EXPECT_EQ(r.layers, std::vector<std::string>{"buildings"});
  EXPECT_EQ(r.margin, 5);
  EXPECT_EQ(r.curve_step_degrees, 2);
  EXPECT_EQ(r.rules[0].action, FeatureAction::Open);
  EXPECT_EQ(r.rules[0].values, (std::vector<std::string>{"wall", "fence"}));
  EXPECT_EQ(r.rules[0].name, "TYPE=wall|fence");
  EXPECT_EQ(r.rules[0].in_out, 0);
  EXPECT_EQ(r.rules[0].height.levels_attribute, "FLOORS");
  EXPECT_EQ(r.rules[0].height.level_height, 4);
  EXPECT_EQ(r.rules[0].height.default_height, 2);
  EXPECT_EQ(r.rules[1].action, FeatureAction::Object);
  EXPECT_EQ(r.rules[1].object_height, 1.0);
  EXPECT_TRUE(r.rules[2].free_space_inside);
  EXPECT_EQ(r.rules[2].name, "rooms");
}

void expect_refused(const std::string& json, const std::string& field) {
  try {
    parse_import_rules(json, "r.json");
    FAIL() << "accepted " << json;
  } catch (const FileFormatError& e) {
    EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
    EXPECT_EQ(std::string(e.what()).rfind("r.json: ", 0), 0u) << e.what();
  }
}

TEST(ImportRules, MalformedRulesAreNamed) {
  expect_refused("{", "expected JSON");
  expect_refused(R"({"rules": []})", "rules");
  expect_refused(R"({"rules": [{"key": "a"}]})", "rules[0].action");
  expect_refused(R"({"rules": [{"action": "wall"}]})", "rules[0].action");
  expect_refused(R"({"rules": [{"action": "open", "colour": 1}]})", "rules[0].colour");
  expect_refused(R"({"rules": [{"action": "open", "in_out": 2}]})", "rules[0].in_out");
  expect_refused(R"({"rules": [{"action": "open", "height": {"default": -1}}]})", "rules[0].height.default");
  expect_refused(R"({"rules": [{"action": "open", "geometry": "curve"}]})", "rules[0].geometry");
  expect_refused(R"({"rules": [{"action": "open", "values": ["x"]}]})", "rules[0].values");
}

TEST(ImportRules, OsmDefaultsFollowTheIssueTable) {
  const ImportRules r = osm_default_rules();
  auto find = [&](const std::string& key, const std::string& value) -> const FeatureRule* {
    for (const FeatureRule& f : r.rules)
      if (f.key == key && (f.values.empty() || std::find(f.values.begin(), f.values.end(), value) != f.values.end()))
        return &f;
    return nullptr;
  };
  ASSERT_TRUE(find("building", "yes"));
  EXPECT_EQ(find("building", "yes")->action, FeatureAction::Closed);
  EXPECT_EQ(find("building", "yes")->height.levels_attribute, "building:levels");
  EXPECT_EQ(find("building", "yes")->height.level_height, 3);
  ASSERT_TRUE(find("barrier", "wall"));
  EXPECT_EQ(find("barrier", "fence")->action, FeatureAction::Open);
  EXPECT_EQ(find("highway", "steps")->action, FeatureAction::Stairs);
  EXPECT_EQ(find("amenity", "bench")->action, FeatureAction::Object);
  EXPECT_EQ(find("indoor", "room")->action, FeatureAction::Closed);
  EXPECT_TRUE(find("indoor", "room")->free_space_inside);
  const auto keys = rule_keys(r);
  EXPECT_NE(std::find(keys.begin(), keys.end(), "building:levels"), keys.end());
}

// Footways, paths and roads are where robots drive (issue table: only steps, walls and
// barriers are obstacles): no default rule may turn them into walls across the campus.
TEST(ImportRules, OsmDefaultsLeaveWaysToDriveOnFree) {
  const ImportRules r = osm_default_rules();
  for (const char* value : {"footway", "path", "pedestrian", "cycleway", "service", "residential", "track"}) {
    for (const FeatureRule& f : r.rules) {
      const bool matches = f.key.empty() || (f.key == "highway" && (f.values.empty() || std::find(f.values.begin(),
                                                                     f.values.end(), value) != f.values.end()));
      EXPECT_FALSE(matches && f.action != FeatureAction::Skip) << "highway=" << value << " matches rule " << f.name;
    }
  }
}

}  // namespace
}  // namespace fleetmap
