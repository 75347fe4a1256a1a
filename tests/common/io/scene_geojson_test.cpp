// common/io/scene_geojson.*: the example room's contents as written in the file, round
// trips (numbers bit for bit, mixed 2D/2.5D elements, awkward text), generated ids, tag
// checks, the tag table, and malformed inputs: each names the feature and the field,
// and nothing is returned.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>

#include "common/io/scene_geojson.h"

namespace fleetmap {
namespace {

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  EXPECT_TRUE(in) << path;
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string room_geojson() { return slurp(FLEETMAP_SOURCE_DIR "/maps/example-room.geojson"); }
std::string room_tags() { return slurp(FLEETMAP_SOURCE_DIR "/maps/example-room.tags.json"); }

const EnvObject* find(const Scene& s, const std::string& id) {
  for (const EnvObject& o : s.objects)
    if (o.id == id) return &o;
  return nullptr;
}

TEST(SceneGeojson, ExampleRoomAsWritten) {
  const Scene s = read_scene_geojson(room_geojson());
  ASSERT_TRUE(s.bounds);
  EXPECT_EQ(*s.bounds, (Polygon{{-0.2, -0.2}, {15.2, -0.2}, {15.2, 15.2}, {-0.2, 15.2}}));
  // door, charger, 3 boxes, small table, 2 cupboards, big table, 4 chairs, 2 shelves,
  // trolley, plant
  EXPECT_EQ(s.objects.size(), 17u);
  EXPECT_EQ(s.avoided.size(), 10u);  // 5 walls, 4 columns, 1 keep-out zone

  const EnvObject* table = find(s, "big-table");
  ASSERT_TRUE(table);
  EXPECT_EQ(table->tag, "table");
  ASSERT_EQ(table->elements.size(), 5u);  // 4 legs + top
  for (int i = 0; i < 4; ++i) EXPECT_EQ(table->elements[i].z, (HeightRange{0, 0.72}));
  EXPECT_EQ(table->elements[4].z, (HeightRange{0.72, 0.76}));
  EXPECT_EQ(table->elements[4].footprint, (Polygon{{6.5, 7}, {8.5, 7}, {8.5, 8}, {6.5, 8}}));

  const EnvObject* chair = find(s, "chair-3");
  ASSERT_TRUE(chair);
  ASSERT_EQ(chair->elements.size(), 6u);  // 4 legs, seat, backrest
  EXPECT_EQ(chair->elements[5].z, (HeightRange{0.47, 0.9}));

  const EnvObject* box = find(s, "box-3");
  ASSERT_TRUE(box);
  ASSERT_EQ(box->elements.size(), 1u);
  EXPECT_EQ(box->elements[0].footprint.size(), 4u);  // the closing position is not kept
  EXPECT_NEAR(polygon_area(box->elements[0].footprint), 0.24, 1e-4);

  const EnvObject* plant = find(s, "plant-1");
  ASSERT_TRUE(plant);
  EXPECT_FALSE(plant->elements.at(0).z);  // 2D
  EXPECT_FALSE(plant->dynamic);
  ASSERT_TRUE(find(s, "trolley-1"));
  EXPECT_TRUE(find(s, "trolley-1")->dynamic);
  EXPECT_EQ(s.avoided.back().id, "keepout-1");
  EXPECT_EQ(s.avoided.back().area.size(), 6u);  // the L-shaped zone
}

TEST(SceneGeojson, ExampleRoomTagsAreKnown) {
  const std::vector<TagInfo> tags = read_tag_table_json(room_tags());
  SceneReadOptions opt;
  opt.check_tags = true;
  for (const TagInfo& t : tags) opt.known_tags.insert(t.tag);
  EXPECT_NO_THROW(read_scene_geojson(room_geojson(), opt));
  ASSERT_GE(tags.size(), 9u);
  EXPECT_EQ(tags[0], (TagInfo{"box", "obstacle", "cardboard box on the floor"}));
  opt.known_tags.erase("chair");
  EXPECT_THROW(read_scene_geojson(room_geojson(), opt), SceneFormatError);
}

TEST(SceneGeojson, ExampleRoomRoundTrip) {
  const Scene s = read_scene_geojson(room_geojson());
  const std::string text = write_scene_geojson(s);
  EXPECT_EQ(read_scene_geojson(text), s);
  EXPECT_EQ(write_scene_geojson(read_scene_geojson(text)), text);  // stable
}

TEST(SceneGeojson, RoundTripAwkwardScene) {
  Scene s;
  s.bounds = Polygon{{-1e6, -1e6}, {1e6, -1e6}, {0, 1e6}};
  const double third = 1.0 / 3, tiny = std::nextafter(0.0, 1.0), sum = 0.1 + 0.2;
  EnvObject a{"a \"quoted\" \\ id \xE6\x9D\xB1", "caf\xC3\xA9", {}, true};
  a.elements.push_back({{{third, sum}, {1, sum}, {1, 2.0 / 3}}, HeightRange{tiny, std::nextafter(0.76, 1.0)}});
  a.elements.push_back({{{5, 5}, {6, 5}, {6, 6}}, std::nullopt});  // 2D beside 2.5D: z has a null
  a.elements.push_back({rectangle_footprint({3, 3}, 0.7, 0.3, 0.5), HeightRange{0.72, 0.76}});
  EnvObject b{"b", "box", {{{{0, 0}, {1, 0}, {0, 1}}, std::nullopt}}, false};  // 2D only: no z written
  s.objects = {a, b};
  s.avoided = {{"col", {{1e-7, 1e-7}, {2, 0}, {2, 2}}}};
  const std::string text = write_scene_geojson(s);
  EXPECT_EQ(read_scene_geojson(text), s);
  EXPECT_NE(text.find("[0.72,0.76]"), std::string::npos);
  EXPECT_NE(text.find("null"), std::string::npos);
  EXPECT_NE(text.find("0.30000000000000004"), std::string::npos);  // shortest round-trip form
}

TEST(SceneGeojson, WriterRefusesWhatTheReaderWould) {
  Scene s;
  s.objects = {{"x", "box", {}, false}};
  EXPECT_THROW(write_scene_geojson(s), std::invalid_argument);
  s.objects = {{"x", "box", {{{{0, 0}, {NAN, 0}, {0, 1}}, std::nullopt}}, false}};
  EXPECT_THROW(write_scene_geojson(s), std::invalid_argument);
  s.objects = {{"x\xFF", "box", {{{{0, 0}, {1, 0}, {0, 1}}, std::nullopt}}, false}};
  EXPECT_THROW(write_scene_geojson(s), std::invalid_argument);
}

// A Feature with this properties text and a unit-square Polygon.
std::string feature(const std::string& props, const std::string& ring = "[[0,0],[1,0],[1,1],[0,1],[0,0]]") {
  return R"({"type":"Feature","properties":{)" + props + R"(},"geometry":{"type":"Polygon","coordinates":[)" + ring +
         "]}}";
}
std::string collection(const std::vector<std::string>& features) {
  std::string out = R"({"type":"FeatureCollection","features":[)";
  for (size_t i = 0; i < features.size(); ++i) out += (i ? "," : "") + features[i];
  return out + "]}";
}

TEST(SceneGeojson, GeneratedIdsAndDefaults) {
  const Scene s = read_scene_geojson(collection({
      feature(R"("tag":"box")"),
      feature(R"("tag":"box","id":"box-1")"),  // taken explicitly: the first box becomes box-2
      feature(R"("tag":"chair")"),
      feature(R"("tag":"box","kind":null,"dynamic":null,"z":null,"name":"from QGIS"})"
              R"(,"unused":{"a":1)"),
      feature(R"("kind":"avoid")"),
      feature(R"("kind":"avoid","id":"avoid-1")"),
  }));
  ASSERT_EQ(s.objects.size(), 4u);
  EXPECT_EQ(s.objects[0].id, "box-2");
  EXPECT_EQ(s.objects[1].id, "box-1");
  EXPECT_EQ(s.objects[2].id, "chair-1");
  EXPECT_EQ(s.objects[3].id, "box-3");
  EXPECT_FALSE(s.objects[3].dynamic);
  EXPECT_FALSE(s.objects[3].elements.at(0).z);
  ASSERT_EQ(s.avoided.size(), 2u);
  EXPECT_EQ(s.avoided[0].id, "avoid-2");
  EXPECT_EQ(s.avoided[1].id, "avoid-1");
  EXPECT_FALSE(s.bounds);
  // A Polygon ring is stored without its closing position, in file order.
  EXPECT_EQ(s.objects[0].elements.at(0).footprint, (Polygon{{0, 0}, {1, 0}, {1, 1}, {0, 1}}));
}

struct Malformed {
  std::string name;
  std::string text;
  int feature;
  std::string field;
  std::string words;  // part of the message
  bool check_tags = false;
};

const std::string kOk = feature(R"("tag":"box")");
const std::string kMulti =
    R"({"type":"Feature","properties":{"tag":"table","z":[[0,0.72],[0.72,0.76]]},"geometry":{"type":"MultiPolygon","coordinates":)";

std::vector<Malformed> malformed_cases() {
  return {
      {"not json", "{\"type\":", -1, "", "expected JSON"},
      {"top level array", "[]", -1, "", "expected a FeatureCollection object"},
      {"wrong document type", R"({"type":"Feature","features":[]})", -1, "type", "\"FeatureCollection\""},
      {"no features", R"({"type":"FeatureCollection"})", -1, "features", "expected a member \"features\""},
      {"features not array", R"({"type":"FeatureCollection","features":{}})", -1, "features", "expected an array"},
      {"feature not object", collection({kOk, "7"}), 1, "", "expected a Feature object"},
      {"feature type", collection({R"({"type":"Point","properties":{"tag":"box"}})"}), 0, "type", "\"Feature\""},
      {"no geometry", collection({R"({"type":"Feature","properties":{"tag":"box"}})"}), 0, "geometry", "none"},
      {"null geometry", collection({R"({"type":"Feature","properties":{"tag":"box"},"geometry":null})"}), 0,
       "geometry", "got null"},
      {"line geometry",
       collection({R"({"type":"Feature","properties":{"tag":"box"},"geometry":{"type":"LineString","coordinates":[[0,0],[1,1]]}})"}),
       0, "geometry.type", "\"LineString\""},
      {"ring not closed", collection({kOk, feature(R"("tag":"box")", "[[0,0],[1,0],[1,1],[0,1]]")}), 1,
       "geometry.coordinates[0]", "closed ring"},
      {"ring too short", collection({feature(R"("tag":"box")", "[[0,0],[1,0],[0,0]]")}), 0,
       "geometry.coordinates[0]", "at least 4 positions, got 3"},
      {"position with z", collection({feature(R"("tag":"box")", "[[0,0],[1,0,2],[1,1],[0,0]]")}), 0,
       "geometry.coordinates[0][1]", "heights go in properties.z"},
      {"position string", collection({feature(R"("tag":"box")", R"([[0,0],[1,0],[1,"1"],[0,0]])")}), 0,
       "geometry.coordinates[0][2][1]", "expected a number"},
      {"coordinate too large", collection({feature(R"("tag":"box")", "[[0,0],[1e8,0],[1,1],[0,0]]")}), 0,
       "geometry.coordinates[0][1][0]", "at most"},
      // nlohmann refuses it while parsing, before any feature is read.
      {"coordinate overflows", collection({feature(R"("tag":"box")", "[[0,0],[1,0],[1,1e999],[0,0]]")}), -1, "",
       "number overflow"},
      {"hole", collection({feature(R"("tag":"box")", "[[0,0],[4,0],[4,4],[0,0]],[[1,1],[2,1],[2,2],[1,1]]")}), 0,
       "geometry.coordinates", "holes are not supported"},
      {"bow-tie", collection({kOk, kOk, feature(R"("tag":"box")", "[[0,0],[2,2],[2,0],[0,2],[0,0]]")}), 2,
       "geometry.coordinates[0]", "crossing"},
      {"repeated point", collection({feature(R"("tag":"box")", "[[0,0],[1,0],[1,0],[1,1],[0,0]]")}), 0,
       "geometry.coordinates[0]", "repeated consecutive"},
      {"collinear ring", collection({feature(R"("tag":"box")", "[[0,0],[1,1],[2,2],[3,3],[0,0]]")}), 0,
       "geometry.coordinates[0]", "non-zero area"},
      {"multipolygon bad second",
       collection({kMulti + R"([[[[0,0],[1,0],[1,1],[0,0]]],[[[0,0],[2,2],[2,0],[0,2],[0,0]]]]}})"}), 0,
       "geometry.coordinates[1][0]", "crossing"},
      {"empty multipolygon", collection({kMulti + "[]}}"}), 0, "geometry.coordinates", "at least 1 polygon"},
      {"z count", collection({kOk, kOk, kOk, kMulti + R"([[[[0,0],[1,0],[1,1],[0,0]]]]}})"}), 3, "properties.z",
       "expected 1 range, one per polygon, got 2"},
      {"z count multi",
       collection({kOk, kOk, kOk,
                   R"({"type":"Feature","properties":{"tag":"table","z":[[0,1]]},"geometry":{"type":"MultiPolygon",)"
                   R"("coordinates":[[[[0,0],[1,0],[1,1],[0,0]]],[[[5,5],[6,5],[6,6],[5,5]]]]}})"}),
       3, "properties.z", "expected 2 ranges, one per polygon, got 1"},
      {"z inverted", collection({feature(R"("tag":"box","z":[[0.76,0.72]])")}), 0, "properties.z[0]", "zmin < zmax"},
      {"z empty range", collection({feature(R"("tag":"box","z":[[0.5,0.5]])")}), 0, "properties.z[0]", "zmin < zmax"},
      {"z below floor", collection({feature(R"("tag":"box","z":[[-0.1,0.5]])")}), 0, "properties.z[0]", "zmin >= 0"},
      {"z not pair", collection({feature(R"("tag":"box","z":[[1]])")}), 0, "properties.z[0]", "[zmin, zmax]"},
      {"z string", collection({feature(R"("tag":"box","z":[[0,"1"]])")}), 0, "properties.z[0][1]", "a number"},
      {"z too high", collection({feature(R"("tag":"box","z":[[0,1001]])")}), 0, "properties.z[0][1]", "at most 1000"},
      {"z not list", collection({feature(R"("tag":"box","z":0.5)")}), 0, "properties.z", "expected an array"},
      {"no tag", collection({kOk, feature(R"("kind":"object")")}), 1, "properties.tag", "got none"},
      {"no properties", collection({R"({"type":"Feature","geometry":{"type":"Polygon","coordinates":[[[0,0],[1,0],[1,1],[0,0]]]}})"}),
       0, "properties.tag", "got none"},
      {"tag number", collection({feature(R"("tag":3)")}), 0, "properties.tag", "expected a string"},
      {"tag empty", collection({feature(R"("tag":"")")}), 0, "properties.tag", "non-empty"},
      {"tag delimiter", collection({feature(R"("tag":"box;1")")}), 0, "properties.tag", "';'"},
      {"tag colon", collection({feature(R"("tag":"box:1")")}), 0, "properties.tag", "':'"},
      {"tag unknown", collection({kOk, feature(R"("tag":"sofa")")}), 1, "properties.tag", "unknown \"sofa\"", true},
      {"dynamic string", collection({feature(R"("tag":"box","dynamic":"yes")")}), 0, "properties.dynamic", "true or false"},
      {"kind unknown", collection({feature(R"("kind":"wall")")}), 0, "properties.kind", "\"avoid\""},
      {"properties array", collection({R"({"type":"Feature","properties":[],"geometry":null})"}), 0, "properties",
       "an object or null"},
      {"id number", collection({feature(R"("tag":"box","id":12)")}), 0, "properties.id", "expected a string"},
      {"duplicate id", collection({feature(R"("tag":"box","id":"b")"), kOk, feature(R"("kind":"avoid","id":"b")")}),
       2, "properties.id", "first in feature 0"},
      {"two bounds", collection({feature(R"("kind":"bounds")"), feature(R"("kind":"bounds")")}), 1, "properties.kind",
       "at most one bounds"},
      {"bounds multipolygon",
       collection({R"({"type":"Feature","properties":{"kind":"bounds"},"geometry":{"type":"MultiPolygon","coordinates":[[[[0,0],[1,0],[1,1],[0,0]]]]}})"}),
       0, "geometry.type", "expected \"Polygon\""},
      {"bounds with id", collection({feature(R"("kind":"bounds","id":"b")")}), 0, "properties.id", "no id"},
      {"avoid with z", collection({feature(R"("kind":"avoid","z":[[0,1]])")}), 0, "properties.z", "only objects"},
      {"avoid with tag", collection({feature(R"("kind":"avoid","tag":"column")")}), 0, "properties.tag", "only objects"},
  };
}

TEST(SceneGeojson, MalformedInputsNameFeatureAndField) {
  const auto cases = malformed_cases();
  ASSERT_GE(cases.size(), 20u);
  for (const Malformed& c : cases) {
    SCOPED_TRACE(c.name);
    SceneReadOptions opt;
    if (c.check_tags) opt = {{"box", "table", "chair"}, true};
    std::optional<Scene> scene;
    try {
      scene = read_scene_geojson(c.text, opt);
      ADD_FAILURE() << "accepted";
    } catch (const SceneFormatError& e) {
      EXPECT_EQ(e.feature(), c.feature) << e.what();
      EXPECT_EQ(e.field(), c.field) << e.what();
      EXPECT_NE(std::string(e.what()).find(c.words), std::string::npos) << e.what();
      const std::string prefix = c.feature < 0 ? "document" : "feature " + std::to_string(c.feature);
      EXPECT_EQ(std::string(e.what()).rfind(prefix, 0), 0u) << e.what();
      if (!c.field.empty()) {
        EXPECT_NE(std::string(e.what()).find("(" + c.field + "): "), std::string::npos) << e.what();
      }
    }
    EXPECT_FALSE(scene.has_value());
  }
}

TEST(SceneGeojson, ErrorTextOfAMalformedZCount) {
  try {
    for (const Malformed& c : malformed_cases())
      if (c.name == "z count multi") read_scene_geojson(c.text);
    FAIL();
  } catch (const SceneFormatError& e) {
    EXPECT_STREQ(e.what(), "feature 3 (properties.z): expected 2 ranges, one per polygon, got 1");
  }
}

TEST(SceneGeojson, TagTable) {
  const std::vector<TagInfo> tags = {{"box", "obstacle", "a box"}, {"door", "landmark", "d \"x\" %;#"},
                                     {"cart", "dynamic", ""}, {"chair", "interactable", "\xC3\xA9"}};
  EXPECT_EQ(read_tag_table_json(write_tag_table_json(tags)), tags);
  EXPECT_EQ(read_tag_table_json(R"([{"tag":"box","class":"obstacle"}])"), (std::vector<TagInfo>{{"box", "obstacle", ""}}));
  EXPECT_TRUE(is_tag_class("landmark"));
  EXPECT_FALSE(is_tag_class("furniture"));
  EXPECT_FALSE(is_tag_class("Obstacle"));

  struct Bad {
    std::string text;
    int entry;
    std::string field;
  };
  for (const Bad& b : std::vector<Bad>{
           {"{}", -1, ""},
           {"[", -1, ""},
           {R"([{"tag":"box","class":"obstacle"},{"tag":"sofa","class":"furniture"}])", 1, "class"},
           {R"([{"tag":"box","class":"obstacle"},{"tag":"box","class":"landmark"}])", 1, "tag"},
           {R"([{"class":"obstacle"}])", 0, "tag"},
           {R"([{"tag":"a:b","class":"obstacle"}])", 0, "tag"},
           {R"([{"tag":"box","class":"obstacle","description":5}])", 0, "description"},
           {R"([3])", 0, ""},
       }) {
    SCOPED_TRACE(b.text);
    try {
      read_tag_table_json(b.text);
      ADD_FAILURE() << "accepted";
    } catch (const SceneFormatError& e) {
      EXPECT_EQ(e.feature(), b.entry) << e.what();
      EXPECT_EQ(e.field(), b.field) << e.what();
      if (b.entry >= 0) {
        EXPECT_EQ(std::string(e.what()).rfind("entry " + std::to_string(b.entry), 0), 0u) << e.what();
      }
    }
  }
}

}  // namespace
}  // namespace fleetmap
