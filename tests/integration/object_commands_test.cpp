// The semantic layer through the real `fleetmap` program (server/cli/object_commands.h):
// objects import|export|list|near, tags, avoid, with their exit codes; a malformed
// GeoJSON names the feature and field and stores nothing; import -> export -> import
// gives the same file.
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include <nlohmann/json.hpp>

#include "common/io/scene_geojson.h"
#include "common/scene/scene_query.h"
#include "protocol/connection.h"
#include "tests/integration/test_db.h"

namespace fleetmap::test {
namespace {

const std::string kRoom = "oc_room", kCopy = "oc_copy";

std::string example() { return source_path("maps/example-room.geojson"); }

void ensure_map(const std::string& name) {
  if (scalar("SELECT COUNT(*) FROM maps WHERE name = '" + name + "'") > 0) return;
  RunResult r = run("fleetmap", "map import " + source_path("maps/example-room.map") + " --name " + name);
  ASSERT_EQ(r.exit_code, 0) << r.err;
}

// Everything an import could touch (ids aside: a re-import numbers rows anew).
std::string fingerprint() {
  auto c = admin();
  mysqlpp::Query q = c->query(
      "SELECT (SELECT COUNT(*) FROM env_objects), (SELECT COUNT(*) FROM object_elements),"
      " (SELECT COUNT(*) FROM avoided_areas), (SELECT COUNT(*) FROM map_bounds), (SELECT COUNT(*) FROM tags),"
      " (SELECT COALESCE(SUM(CRC32(CONCAT_WS(',', map_id, object_key, tag))), 0) FROM env_objects),"
      " (SELECT COALESCE(SUM(CRC32(CONCAT_WS(',', map_id, ord, ST_AsText(footprint), zmin, zmax))), 0) FROM object_elements)");
  mysqlpp::StoreQueryResult r = q.store();
  std::string s;
  for (size_t i = 0; i < r.num_fields(); ++i) s += std::string(r[0][i]) + "/";
  return s;
}

std::vector<std::vector<std::string>> tsv(const std::string& out) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream in(out);
  std::string line;
  while (std::getline(in, line)) {
    std::vector<std::string> cells;
    std::istringstream ls(line);
    std::string cell;
    while (std::getline(ls, cell, '\t')) cells.push_back(cell);
    rows.push_back(cells);
  }
  return rows;
}

class ObjectCommands : public ::testing::Test {
 protected:
  void SetUp() override {
    ensure_map(kRoom);
    RunResult r = run("fleetmap", "objects import " + kRoom + " " + example() + " --replace");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    ASSERT_NE(r.out.find("17 objects"), std::string::npos) << r.out;
  }
};

TEST_F(ObjectCommands, ImportRefusesExistingKeysAndMalformedFilesAndStoresNothing) {
  const std::string before = fingerprint();
  RunResult r = run("fleetmap", "objects import " + kRoom + " " + example());
  EXPECT_EQ(r.exit_code, 4);
  EXPECT_NE(r.err.find("--replace"), std::string::npos) << r.err;

  nlohmann::json j = nlohmann::json::parse(read_file(example()));
  const std::string bad = temp_path("oc_bad.geojson");
  // A reversed height range deep in the file.
  nlohmann::json k = j;
  k["features"][9]["properties"]["z"] = nlohmann::json::array({nlohmann::json::array({1.0, 0.5})});
  write_file(bad, k.dump());
  r = run("fleetmap", "objects import " + kRoom + " " + bad + " --replace");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find(bad + ": feature 9 (properties.z"), std::string::npos) << r.err;
  // A coordinate that is not a number.
  k = j;
  k["features"][4]["geometry"]["coordinates"][0][1][0] = "x";
  write_file(bad, k.dump());
  r = run("fleetmap", "objects import " + kRoom + " " + bad + " --replace");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find(bad + ": feature 4 (geometry.coordinates"), std::string::npos) << r.err;
  // A tag the vocabulary does not have.
  k = j;
  k["features"][3]["properties"]["tag"] = "oc_sofa";
  write_file(bad, k.dump());
  r = run("fleetmap", "objects import " + kRoom + " " + bad + " --replace");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find(bad + ": feature 3 (properties.tag)"), std::string::npos) << r.err;
  // Not JSON at all; an unknown map; a missing file.
  write_file(bad, "{\"type\": \"FeatureCollection\", \"features\": [");
  EXPECT_EQ(run("fleetmap", "objects import " + kRoom + " " + bad).exit_code, 2);
  r = run("fleetmap", "objects import oc_no_map " + example());
  EXPECT_EQ(r.exit_code, 4);
  EXPECT_NE(r.err.find("no map named 'oc_no_map'"), std::string::npos) << r.err;
  EXPECT_EQ(run("fleetmap", "objects import " + kRoom + " /nonexistent.geojson").exit_code, 1);
  EXPECT_EQ(fingerprint(), before);

  // --add-tags takes the unknown tag in as an obstacle.
  k = j;
  k["features"][3]["properties"]["tag"] = "oc_sofa";
  write_file(bad, k.dump());
  r = run("fleetmap", "objects import " + kRoom + " " + bad + " --replace --add-tags");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("tag added: oc_sofa (obstacle)"), std::string::npos) << r.out;
  ASSERT_EQ(run("fleetmap", "objects import " + kRoom + " " + example() + " --replace").exit_code, 0);
  execute(*admin(), "DELETE FROM tags WHERE tag = 'oc_sofa'");
  EXPECT_EQ(fingerprint(), before);
}

TEST_F(ObjectCommands, ExportImportExportIsTheSameFile) {
  ensure_map(kCopy);
  const std::string first = temp_path("oc_first.geojson"), second = temp_path("oc_second.geojson");
  RunResult r = run("fleetmap", "objects export " + kRoom + " --crs map -o " + first);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = run("fleetmap", "objects import " + kCopy + " " + first + " --replace");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = run("fleetmap", "objects export " + kCopy + " --crs map -o " + second);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(read_file(second), read_file(first));
  // And the scene is the example's.
  EXPECT_EQ(read_scene_geojson(read_file(first)), read_scene_geojson(read_file(example())));
  r = run("fleetmap", "objects export " + kRoom + " --crs map");
  EXPECT_EQ(r.out, read_file(first));
  // A map without a georeference has no WGS 84, which GeoJSON holds without --crs map.
  r = run("fleetmap", "objects export " + kRoom);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--crs map"), std::string::npos) << r.err;
  EXPECT_EQ(run("fleetmap", "objects export oc_no_map").exit_code, 4);
}

TEST_F(ObjectCommands, ListAndNearPrintWhatTheReferenceFinds) {
  const Scene scene = read_scene_geojson(read_file(example()));
  RunResult r = run("fleetmap", "objects list " + kRoom);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  auto rows = tsv(r.out);
  ASSERT_EQ(rows.size(), scene.objects.size() + 1);
  EXPECT_EQ(rows[0][0], "key");
  r = run("fleetmap", "objects list " + kRoom + " --tag chair");
  EXPECT_EQ(tsv(r.out).size(), 5u);

  for (const auto& [x, y, tag, k] : std::vector<std::tuple<double, double, std::string, int>>{
           {7.5, 3, "box", 2}, {-1.25, 4.5, "chair", 3}, {12, 4, "trolley", 1}, {3, 14, "door", 2}}) {
    r = run("fleetmap", "objects near " + kRoom + " " + std::to_string(x) + " " + std::to_string(y) + " --tag " + tag +
                            " -k " + std::to_string(k));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    rows = tsv(r.out);
    const auto want = nearest_objects(scene, {x, y}, tag, k);
    ASSERT_EQ(rows.size(), want.size() + 1) << r.out;
    for (size_t i = 0; i < want.size(); ++i) {
      EXPECT_EQ(rows[i + 1][0], want[i].id);
      EXPECT_NEAR(std::stod(rows[i + 1][8]), want[i].distance, 1e-9);
    }
  }
  r = run("fleetmap", "objects list " + kRoom + " --within 7.5 3 4");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  size_t within = 0;
  for (const EnvObject& o : scene.objects) within += distance_to_object({7.5, 3}, o) <= 4;
  EXPECT_EQ(tsv(r.out).size(), within + 1);

  EXPECT_EQ(run("fleetmap", "objects near oc_no_map 1 2 --tag box").exit_code, 4);
  EXPECT_EQ(run("fleetmap", "objects near " + kRoom + " 1 2").exit_code, 64);  // --tag is required
  EXPECT_EQ(run("fleetmap", "objects near " + kRoom + " 1 2 --tag box -k 0").exit_code, 64);
  EXPECT_EQ(run("fleetmap", "objects near " + kRoom + " 1 nan --tag box").exit_code, 2);
  EXPECT_EQ(run("fleetmap", "objects list " + kRoom + " --within 1 2 -3").exit_code, 2);
  EXPECT_EQ(run("fleetmap", "objects --help").exit_code, 0);
}

TEST_F(ObjectCommands, AvoidAndTags) {
  RunResult r = run("fleetmap", "avoid add " + kRoom + " --wkt 'POLYGON((6 6, 7 6, 7 7, 6 7, 6 6))' --id oc-a");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out, "oc-a\n");
  EXPECT_EQ(run("fleetmap", "avoid add " + kRoom + " --wkt 'POLYGON((6 6, 7 6, 7 7))' --id oc-a").exit_code, 4);
  r = run("fleetmap", "avoid add " + kRoom + " --wkt 'POLYGON((0 0, 1 1, 1 0, 0 1))'");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("avoided area"), std::string::npos) << r.err;
  EXPECT_EQ(run("fleetmap", "avoid add " + kRoom + " --wkt 'POLYGON((0 0, 1 1'").exit_code, 2);
  EXPECT_EQ(run("fleetmap", "avoid add oc_no_map --wkt 'POLYGON((6 6, 7 6, 7 7))'").exit_code, 4);
  r = run("fleetmap", "avoid at " + kRoom + " 6.5 6.5");
  EXPECT_EQ(r.out, "oc-a\n");
  r = run("fleetmap", "avoid at " + kRoom + " 2.5 10.5");
  EXPECT_EQ(r.out, "keepout-1\n");
  r = run("fleetmap", "avoid list " + kRoom);
  EXPECT_NE(r.out.find("oc-a\tPOLYGON((6 6,7 6,7 7,6 7,6 6))\n"), std::string::npos) << r.out;
  // The example's areas are part of the export, the added one too.
  EXPECT_NE(run("fleetmap", "objects export " + kRoom + " --crs map").out.find("\"oc-a\""), std::string::npos);

  r = run("fleetmap", "tags list");
  EXPECT_NE(r.out.find("door\tlandmark\t"), std::string::npos) << r.out;
  r = run("fleetmap", "tags set oc_cart dynamic --description 'a cart'");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(run("fleetmap", "tags list").out.find("oc_cart\tdynamic\ta cart\n"), std::string::npos);
  EXPECT_EQ(run("fleetmap", "tags set oc_cart obstacle").exit_code, 0);
  EXPECT_NE(run("fleetmap", "tags list").out.find("oc_cart\tobstacle\ta cart\n"), std::string::npos);
  EXPECT_EQ(run("fleetmap", "tags set oc_cart furniture").exit_code, 2);
  EXPECT_EQ(run("fleetmap", "tags set a:b obstacle").exit_code, 2);
  r = run("fleetmap", "tags import " + source_path("maps/example-room.tags.json"));
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("11 tags"), std::string::npos) << r.out;
  execute(*admin(), "DELETE FROM tags WHERE tag = 'oc_cart'");
}

}  // namespace
}  // namespace fleetmap::test
