// `map import --replace` keeps what depends on the map (protocol/map_replace.h): the maps
// row keeps its id, robots stay assigned, objects, avoided areas, bounds, topology and the
// georeference stay unless dropped; a replace that strands something needs --force; a
// failure half-way leaves the old map; the server serves the new map after a replace.
// Real `fleetmap`, real MariaDB; positions and expectations worked out by hand.
#include <gtest/gtest.h>

#include "common/io/seed_format.h"
#include "common/slicing/map_slice.h"
#include "protocol/connection.h"
#include "protocol/map_store.h"
#include "protocol/scene_store.h"
#include "protocol/topo_store.h"
#include "tests/integration/server_fixture.h"
#include "tests/integration/test_db.h"

namespace fleetmap::test {
namespace {

const std::string kMap = "mr_map";

std::vector<Point> box(double x0, double y0, double x1, double y1) { return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}; }

Obstacle chain(int id, ShapeType type, const std::vector<Point>& pts, double h, bool closed) {
  Obstacle o;
  o.id = id;
  o.type = type;
  o.semantic = "block";
  const size_t n = closed ? pts.size() : pts.size() - 1;
  for (size_t i = 0; i < n; ++i) o.segments.push_back({pts[i], pts[(i + 1) % pts.size()], h, 0, "wall", ""});
  return o;
}

// A: a 20 x 10 room with one wall along the top.
Map map_a() {
  Map m;
  m.border = Border::from_rect({0, 0, 20, 10});
  m.obstacles.push_back(chain(1, ShapeType::OpenPolygon, {{1, 9}, {10, 9}, {19, 9}}, 2, false));
  m.compute_bounds();
  return m;
}

// B: the same room, the wall moved down, and a solid block (counter-clockwise: free space
// outside) at (16, 1)-(18, 4), where nothing stands.
Map map_b() {
  Map m;
  m.border = Border::from_rect({0, 0, 20, 10});
  m.obstacles.push_back(chain(1, ShapeType::OpenPolygon, {{1, 8}, {10, 8}, {19, 8}}, 2, false));
  m.obstacles.push_back(chain(2, ShapeType::ClosedPolygon, box(16, 1, 18, 4), 1, true));
  m.compute_bounds();
  return m;
}

// C: half the room (x up to 10), a solid block at (4, 4)-(6, 6) under robot mr_r1.
Map map_c() {
  Map m;
  m.border = Border::from_rect({0, 0, 10, 10});
  m.obstacles.push_back(chain(1, ShapeType::ClosedPolygon, box(4, 4, 6, 6), 1, true));
  m.compute_bounds();
  return m;
}

std::string seed_file(const std::string& name, const Map& m) {
  const std::string path = temp_path(name + ".map");
  write_file(path, write_seed(m));
  return path;
}

long long map_id() { return scalar("SELECT id FROM maps WHERE name = '" + kMap + "'"); }
long long count_of(const std::string& table) {
  return scalar("SELECT COUNT(*) FROM " + table + " WHERE map_id = " + std::to_string(map_id()));
}

// Everything a replace could touch, in one text.
std::string fingerprint() {
  auto c = admin();
  const std::string id = std::to_string(map_id());
  mysqlpp::Query q = c->query(
      "SELECT m.id, m.revision, m.mx1, m.my1, m.mx4, m.my4, m.obstacles, m.segments, COALESCE(m.geo_crs, 'none'),"
      " (SELECT COALESCE(SUM(CRC32(CONCAT_WS(',', obstacle_ord, ord, ax, ay, bx, `by`, h))), 0) FROM segments"
      "   WHERE map_id = m.id),"
      " (SELECT GROUP_CONCAT(db_user, ':', COALESCE(map_id, 'none') ORDER BY db_user) FROM robots"
      "   WHERE db_user LIKE 'mr\\_%'),"
      " (SELECT COUNT(*) FROM env_objects WHERE map_id = m.id), (SELECT COUNT(*) FROM object_elements WHERE map_id = m.id),"
      " (SELECT COUNT(*) FROM avoided_areas WHERE map_id = m.id), (SELECT COUNT(*) FROM map_bounds WHERE map_id = m.id),"
      " (SELECT COUNT(*) FROM topo_graphs WHERE map_id = m.id), (SELECT COUNT(*) FROM topo_nodes WHERE map_id = m.id),"
      " (SELECT COUNT(*) FROM topo_edges WHERE map_id = m.id)"
      " FROM maps m WHERE m.id = " + id);
  mysqlpp::StoreQueryResult r = q.store();
  std::string s;
  for (size_t i = 0; i < r.num_fields(); ++i) s += std::string(r[0][i].is_null() ? "NULL" : r[0][i].c_str()) + "/";
  return s;
}

bool has_line(const std::string& text, const std::string& line) {
  return text.find(line + "\n") != std::string::npos;
}

class MapReplace : public ::testing::Test {
 protected:
  // A fresh map A with one of every dependent:
  //   robot mr_r1   last pose (5, 5), initial pose (5, 4), open task to (8, 5), a done task at (30, 30)
  //   robot mr_r2   last pose (25, 5): off the map already
  //   object mr_box (2, 2)-(3, 3); avoided areas mr_near (6, 1)-(7, 2), mr_far (12, 1)-(13, 2)
  //   bounds (0.5, 0.5)-(19.5, 9.5); topology nodes 1 (3, 5), 2 'far' (15, 5); georeference
  void SetUp() override {
    auto a = admin();
    // Rows without accounts (the server test's robots have theirs, made by add_robot).
    execute(*a, "DELETE t FROM tasks t JOIN robots r ON r.id = t.robot_id WHERE r.db_user IN ('mr_r1', 'mr_r2')");
    execute(*a, "DELETE FROM robots WHERE db_user IN ('mr_r1', 'mr_r2')");
    op_ = connect_as(Role::Operator);
    MapStore store(*op_);
    store.remove(kMap);
    store.import(map_a(), kMap, "a", false);
    const std::string id = std::to_string(map_id());
    execute(*a, "INSERT INTO robots (db_user, map_id, x, y, theta, ini_x, ini_y, ini_theta) VALUES"
                " ('mr_r1', " + id + ", 5, 5, 0, 5, 4, 0), ('mr_r2', " + id + ", 25, 5, 0, NULL, NULL, NULL)");
    execute(*a, "INSERT INTO tasks (robot_id, goal_x, goal_y, state) SELECT id, 8, 5, 'active' FROM robots"
                " WHERE db_user = 'mr_r1'");
    execute(*a, "INSERT INTO tasks (robot_id, goal_x, goal_y, state) SELECT id, 30, 30, 'done' FROM robots"
                " WHERE db_user = 'mr_r1'");
    Scene scene;
    scene.objects.push_back({"mr_box", "box", {{box(2, 2, 3, 3), std::nullopt}}, false});
    scene.avoided.push_back({"mr_near", box(6, 1, 7, 2)});
    scene.avoided.push_back({"mr_far", box(12, 1, 13, 2)});
    scene.bounds = box(0.5, 0.5, 19.5, 9.5);
    SceneStore(*op_).import(kMap, scene, {.replace = true});
    TopoGraph g;
    g.add_node({1, {3, 5}, ""});
    g.add_node({2, {15, 5}, "far"});
    g.add_edge({.a = 1, .b = 2});
    TopoStore(*op_).import(kMap, g, "test", true);
    store.set_georef(kMap, MapGeoref{"EPSG:26910", 490000, 5450000, 0.25, 1});
  }
  std::unique_ptr<mysqlpp::Connection> op_;
};

TEST_F(MapReplace, KeepsTheIdTheRobotsAndEveryDependent) {
  const long long id = map_id();
  RunResult r = run("fleetmap", "map import " + seed_file("mr_b", map_b()) + " --name " + kMap + " --replace");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("replaced '" + kMap + "': 2 obstacles, 6 segments"), std::string::npos) << r.out;
  EXPECT_TRUE(has_line(r.out,
                       "  kept: 2 robots (stay assigned), 1 open task, 1 object, 2 avoided areas, bounds, topology "
                       "(2 nodes, 1 edge), georeference (EPSG:26910)"))
      << r.out;
  EXPECT_TRUE(has_line(r.out, "  dropped: nothing")) << r.out;

  EXPECT_EQ(map_id(), id);
  EXPECT_EQ(scalar("SELECT revision FROM maps WHERE id = " + std::to_string(id)), 2);
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM robots WHERE db_user LIKE 'mr\\_%' AND map_id = " + std::to_string(id)), 2);
  EXPECT_EQ(count_of("env_objects"), 1);
  EXPECT_EQ(count_of("object_elements"), 1);
  EXPECT_EQ(count_of("avoided_areas"), 2);
  EXPECT_EQ(count_of("map_bounds"), 1);
  EXPECT_EQ(count_of("topo_nodes"), 2);
  EXPECT_EQ(count_of("topo_edges"), 1);
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM maps WHERE id = " + std::to_string(id) +
                   " AND geo_crs = 'EPSG:26910' AND geo_tx = 490000 AND geo_rotation = 0.25"),
            1);
  // The segments are B's, and only B's.
  RunResult e = run("fleetmap", "map export " + kMap);
  ASSERT_EQ(e.exit_code, 0) << e.err;
  EXPECT_EQ(read_seed(e.out), map_b());
  EXPECT_EQ(count_of("segments"), 6);
  EXPECT_EQ(count_of("obstacles"), 2);
}

TEST_F(MapReplace, DropDeletesOnlyWhatItNames) {
  const long long id = map_id();
  const std::string file = seed_file("mr_b", map_b());
  RunResult r = run("fleetmap", "map import " + file + " --name " + kMap + " --replace --drop objects,topology,georef");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(has_line(r.out, "  kept: 2 robots (stay assigned), 1 open task, 2 avoided areas, bounds")) << r.out;
  EXPECT_TRUE(has_line(r.out, "  dropped: 1 object, topology (2 nodes, 1 edge), georeference (EPSG:26910)")) << r.out;
  EXPECT_EQ(count_of("env_objects"), 0);
  EXPECT_EQ(count_of("object_elements"), 0);
  EXPECT_EQ(count_of("topo_graphs") + count_of("topo_nodes") + count_of("topo_edges"), 0);
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM maps WHERE id = " + std::to_string(id) + " AND geo_crs IS NULL"), 1);
  EXPECT_EQ(count_of("avoided_areas"), 2);
  EXPECT_EQ(count_of("map_bounds"), 1);

  r = run("fleetmap", "map import " + file + " --name " + kMap + " --replace --drop all");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(has_line(r.out, "  kept: 2 robots (stay assigned), 1 open task")) << r.out;
  EXPECT_TRUE(has_line(r.out, "  dropped: 2 avoided areas, bounds")) << r.out;
  EXPECT_EQ(count_of("avoided_areas") + count_of("map_bounds"), 0);
  EXPECT_EQ(map_id(), id);
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM robots WHERE db_user LIKE 'mr\\_%' AND map_id = " + std::to_string(id)), 2);

  // Flags the command line refuses, before anything is read.
  const std::string before = fingerprint();
  for (const std::string& args : {std::string(" --drop objects"), std::string(" --force"),
                                  std::string(" --replace --drop robots")}) {
    SCOPED_TRACE(args);
    RunResult bad = run("fleetmap", "map import " + file + " --name " + kMap + args);
    EXPECT_EQ(bad.exit_code, 64) << bad.err;
  }
  EXPECT_EQ(fingerprint(), before);
}

TEST_F(MapReplace, StrandingNeedsForceAndIsListed) {
  const std::string file = seed_file("mr_c", map_c());
  const std::string before = fingerprint();
  RunResult r = run("fleetmap", "map import " + file + " --name " + kMap + " --replace");
  EXPECT_EQ(r.exit_code, 4) << r.err;
  EXPECT_NE(r.err.find("replacing map '" + kMap + "' would strand 5 dependents"), std::string::npos) << r.err;
  const std::string border = "outside the border (0, 10)-(10, 0)";
  EXPECT_TRUE(has_line(r.err, "  robot mr_r1: last pose (5, 5): inside obstacle 1 'block'")) << r.err;
  EXPECT_TRUE(has_line(r.err, "  robot mr_r1: initial pose (5, 4): inside obstacle 1 'block'")) << r.err;  // on its edge
  EXPECT_TRUE(has_line(r.err, "  avoided area mr_far: vertex (12, 1) " + border)) << r.err;
  EXPECT_NE(r.err.find("  bounds: vertex (19.5, "), std::string::npos) << r.err;
  EXPECT_TRUE(has_line(r.err, "  topology node 2 'far' (15, 5): " + border)) << r.err;
  // Well placed on C: the task's goal (8, 5), the object, mr_near, node 1; off A already: mr_r2.
  for (const char* fine : {"task", "mr_box", "mr_near", "node 1", "mr_r2"})
    EXPECT_EQ(r.err.find(fine), std::string::npos) << fine << "\n" << r.err;
  EXPECT_NE(r.err.find("--force"), std::string::npos) << r.err;
  EXPECT_EQ(fingerprint(), before);

  // Dropping the areas and bounds leaves three; --force keeps them and says so.
  r = run("fleetmap", "map import " + file + " --name " + kMap + " --replace --drop areas,bounds");
  EXPECT_EQ(r.exit_code, 4) << r.err;
  EXPECT_NE(r.err.find("would strand 3 dependents"), std::string::npos) << r.err;
  EXPECT_EQ(fingerprint(), before);
  r = run("fleetmap", "map import " + file + " --name " + kMap + " --replace --force");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(has_line(r.out, "  stranded (kept, --force): 5")) << r.out;
  EXPECT_TRUE(has_line(r.out, "    robot mr_r1: last pose (5, 5): inside obstacle 1 'block'")) << r.out;
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM robots WHERE db_user = 'mr_r1' AND map_id = " + std::to_string(map_id())), 1);
  EXPECT_EQ(count_of("segments"), 4);
  EXPECT_EQ(count_of("topo_nodes"), 2);
}

TEST_F(MapReplace, FailureHalfWayLeavesTheOldMap) {
  // More segments than one INSERT batch carries, so the progress report comes between two.
  Map big;
  big.border = Border::from_rect({0, 0, 20, 10});
  int id = 1;
  for (int i = 0; i < 50; ++i)
    for (int j = 0; j < 50; ++j) {
      const double x = 0.1 + 0.39 * i, y = 0.1 + 0.19 * j;
      big.obstacles.push_back(chain(id++, ShapeType::OpenPolygon, {{x, y}, {x + 0.1, y}, {x + 0.1, y + 0.1}}, 1, false));
    }
  big.compute_bounds();
  ASSERT_GT(big.segment_count(), 4000u);

  const std::string before = fingerprint();
  MapImportOptions o;
  o.replace = true;
  o.drop = MapDrop::all();
  size_t calls = 0;
  o.progress = [&](size_t done, size_t total) {
    ++calls;
    if (done < total) throw std::runtime_error("interrupted");
  };
  EXPECT_THROW(MapStore(*op_).import(big, kMap, "big", o), std::runtime_error);
  EXPECT_EQ(calls, 1u);
  EXPECT_EQ(fingerprint(), before);
  EXPECT_EQ(MapStore(*op_).load(kMap), map_a());

  // The same import without the failure goes through, and the robots are still on the map.
  o.progress = {};
  const MapImportReport r = MapStore(*op_).import(big, kMap, "big", o);
  EXPECT_TRUE(r.replaced);
  EXPECT_EQ(r.map_id, static_cast<unsigned>(map_id()));
  EXPECT_EQ(count_of("segments"), static_cast<long long>(big.segment_count()));
  EXPECT_EQ(r.replace.kept.robots, 2u);
  EXPECT_EQ(r.replace.dropped.objects, 1u);
  EXPECT_EQ(r.replace.dropped.areas, 2u);
}

TEST_F(MapReplace, ImportsGeoreferenceReplacesTheKeptOne) {
  MapImportOptions o;
  o.replace = true;
  o.georef = MapGeoref{"EPSG:32633", 1, 2, 0, 1};
  const MapImportReport r = MapStore(*op_).import(map_b(), kMap, "b", o);
  EXPECT_TRUE(r.replace.georef_replaced);
  EXPECT_FALSE(r.replace.kept.georef);
  const MapInfo info = MapStore(*op_).info(kMap);
  ASSERT_TRUE(info.georef);
  EXPECT_EQ(info.georef->crs, "EPSG:32633");
  EXPECT_EQ(info.revision, 2u);
}

// The server caches whole maps and slices by map id; a replace keeps the id, so the
// next Ready must bring the new map, to a robot with and to one without a laser height.
TEST_F(MapReplace, TheServerServesTheNewMap) {
  SceneStore(*op_).import(kMap, Scene{}, {.replace = true});  // the sliced robot's map: the segments alone
  const std::string plain_pw = add_robot("mr_plain", kMap);
  const std::string sliced_pw = add_robot("mr_sliced", kMap);
  ASSERT_EQ(run("fleetmap", "robot set mr_sliced --laser-height 0.5").exit_code, 0);
  ServerProcess server("", "mr_server.log");
  SqlRobot plain("mr_plain", plain_pw), sliced("mr_sliced", sliced_pw);
  int magic = 3;
  auto map_of = [&magic](SqlRobot& robot) {
    robot.send("Ready", "{\"magic\": " + std::to_string(++magic) + "}");
    const auto a = robot.receive(2);
    if (a.size() != 2 || a[1].op != "SetMap" || !a[1].payload) return std::string("no SetMap");
    return write_seed(read_seed(*a[1].payload));
  };
  EXPECT_EQ(map_of(plain), write_seed(map_a()));
  EXPECT_EQ(map_of(sliced), write_seed(slice_at_height(map_a(), 0.5)));
  RunResult r = run("fleetmap", "map import " + seed_file("mr_b", map_b()) + " --name " + kMap + " --replace");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(map_of(plain), write_seed(map_b()));
  EXPECT_EQ(map_of(sliced), write_seed(slice_at_height(map_b(), 0.5)));
  if (HasFailure()) std::cerr << "server log:\n" << read_file(temp_path("mr_server.log")).substr(0, 20000);
}

}  // namespace
}  // namespace fleetmap::test
