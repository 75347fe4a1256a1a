// The semantic layer in a real MariaDB (protocol/scene_store.h): the example
// scene stored and read back, nearest objects and avoided areas against the brute-force
// reference of common/scene/scene_query.h, imports that fail change nothing, --replace, tags,
// the spatial index, observations and their expiry, the inspector's views and the SQL
// of docs/semantic-layer.md.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "common/io/scene_geojson.h"
#include "common/scene/scene_query.h"
#include "protocol/connection.h"
#include "protocol/map_store.h"
#include "protocol/scene_store.h"
#include "tests/integration/test_db.h"

namespace fleetmap::test {
namespace {

Scene example_scene() { return read_scene_geojson(read_file(source_path("maps/example-room.geojson"))); }

void ensure_map(const std::string& name) {
  if (scalar("SELECT COUNT(*) FROM maps WHERE name = '" + name + "'") > 0) return;
  RunResult r = run("fleetmap", "map import " + source_path("maps/example-room.map") + " --name " + name);
  ASSERT_EQ(r.exit_code, 0) << r.err;
}

// A map holding the example scene, freshly imported.
class SceneStoreTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ensure_map(kMap);
    c_ = connect_as(Role::Operator);
    scene_ = example_scene();
    SceneStore(*c_).import(kMap, scene_, {.replace = true});
  }
  static constexpr const char* kMap = "ss_room";
  std::unique_ptr<mysqlpp::Connection> c_;
  Scene scene_;
};

// Everything an import could touch, in one fingerprint.
std::string fingerprint() {
  auto c = admin();
  mysqlpp::Query q = c->query(
      "SELECT (SELECT COUNT(*) FROM env_objects), (SELECT COUNT(*) FROM object_elements),"
      " (SELECT COUNT(*) FROM avoided_areas), (SELECT COUNT(*) FROM map_bounds), (SELECT COUNT(*) FROM tags),"
      " (SELECT COALESCE(SUM(CRC32(CONCAT_WS(',', id, map_id, object_key, tag, dynamic))), 0) FROM env_objects),"
      " (SELECT COALESCE(SUM(CRC32(CONCAT_WS(',', object_id, ord, ST_AsText(footprint), zmin, zmax))), 0) FROM object_elements),"
      " (SELECT COALESCE(SUM(CRC32(CONCAT_WS(',', id, area_key, ST_AsText(area)))), 0) FROM avoided_areas),"
      " (SELECT COALESCE(SUM(CRC32(CONCAT_WS(',', map_id, ST_AsText(bounds)))), 0) FROM map_bounds),"
      " (SELECT COALESCE(SUM(CRC32(CONCAT_WS(',', tag, class, description))), 0) FROM tags)");
  mysqlpp::StoreQueryResult r = q.store();
  std::string s;
  for (size_t i = 0; i < r.num_fields(); ++i) s += std::string(r[0][i]) + "/";
  return s;
}

std::string text(mysqlpp::Connection& c, const std::string& sql) {
  mysqlpp::Query q = c.query(sql);
  mysqlpp::StoreQueryResult r = q.store();
  return r.empty() || r[0][0].is_null() ? "" : std::string(r[0][0]);
}

// Equal up to the order of objects whose distances differ by at most 1e-9.
void expect_same_nearest(const std::vector<ObjectRow>& got, const std::vector<NearObject>& want, const std::string& where) {
  ASSERT_EQ(got.size(), want.size()) << where;
  for (size_t i = 0; i < want.size(); ++i) {
    ASSERT_TRUE(got[i].distance) << where;
    EXPECT_NEAR(*got[i].distance, want[i].distance, 1e-9) << where << " rank " << i;
    if (got[i].key == want[i].id) continue;
    // A tie: the key must be among the reference's objects at (nearly) that distance.
    bool tied = false;
    for (const NearObject& w : want)
      tied = tied || (w.id == got[i].key && std::abs(w.distance - want[i].distance) <= 1e-9);
    EXPECT_TRUE(tied) << where << " rank " << i << ": got " << got[i].key << ", expected " << want[i].id;
  }
}

TEST_F(SceneStoreTest, ExampleSceneReadsBackEqual) {
  SceneStore store(*c_);
  const Scene back = store.load(kMap);
  EXPECT_EQ(back, scene_);
  EXPECT_EQ(write_scene_geojson(back), write_scene_geojson(scene_));
  const std::string mid = std::to_string(scalar(std::string("SELECT id FROM maps WHERE name = '") + kMap + "'"));
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM env_objects WHERE map_id = " + mid), static_cast<long long>(scene_.objects.size()));
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM avoided_areas WHERE map_id = " + mid), static_cast<long long>(scene_.avoided.size()));
  // The stored polygons are valid and their areas are the model's.
  auto a = admin();
  mysqlpp::Query q = a->query("SELECT o.object_key, e.ord, ST_Area(e.footprint), ST_IsClosed(ST_ExteriorRing(e.footprint)) FROM object_elements e"
                              " JOIN env_objects o ON o.id = e.object_id WHERE o.map_id = " + mid);
  size_t elements = 0;
  for (const mysqlpp::Row& r : q.store()) {
    const std::string key(r[0]);
    const size_t ord = std::stoul(std::string(r[1]));
    for (const EnvObject& o : scene_.objects) {
      if (o.id == key) {
        EXPECT_NEAR(std::stod(std::string(r[2])), polygon_area(o.elements.at(ord).footprint), 1e-9) << key;
      }
    }
    EXPECT_EQ(std::string(r[3]), "1") << key;
    ++elements;
  }
  size_t want = 0;
  for (const EnvObject& o : scene_.objects) want += o.elements.size();
  EXPECT_EQ(elements, want);
}

TEST_F(SceneStoreTest, NearAndAvoidedAreasEqualTheBruteForceReferenceOn1000Points) {
  SceneStore store(*c_);
  std::mt19937 rng(8);
  const Rect b = polygon_bounds(*scene_.bounds);
  std::uniform_real_distribution<double> ux(b.xmin - 3, b.xmax + 3), uy(b.ymin - 3, b.ymax + 3);
  const std::vector<std::string> tags = {"", "box", "chair", "door", "table", "shelf", "trolley", "column"};
  size_t inside_avoided = 0, inside_object = 0, short_lists = 0;
  for (int i = 0; i < 1000; ++i) {
    Point p{ux(rng), uy(rng)};
    // Some points inside footprints (the mean of a convex ring's vertices), some exactly
    // on a vertex of an avoided area (the outline counts as inside).
    if (i % 10 == 3) {
      const Polygon& ring = scene_.objects[rng() % scene_.objects.size()].elements[0].footprint;
      p = {0, 0};
      for (Point v : ring) p = p + (1.0 / ring.size()) * v;
    } else if (i % 25 == 7) {
      const Polygon& ring = scene_.avoided[rng() % scene_.avoided.size()].area;
      p = ring[rng() % ring.size()];
    }
    const std::string& tag = tags[i % tags.size()];
    const int k = 1 + i % 5;
    const std::string where = "point " + std::to_string(i) + " (" + std::to_string(p.x) + ", " + std::to_string(p.y) +
                              ") tag '" + tag + "' k " + std::to_string(k);
    const auto want = nearest_objects(scene_, p, tag, k);
    expect_same_nearest(store.near(kMap, p, tag, k), want, where);
    short_lists += want.size() < static_cast<size_t>(k);
    bool in_some = false;
    for (const EnvObject& o : scene_.objects) in_some = in_some || distance_to_object(p, o) == 0;
    inside_object += in_some;
    const auto areas = store.avoided_areas_containing(kMap, p);
    EXPECT_EQ(areas, containing_avoided_areas(scene_, p)) << where;
    inside_avoided += !areas.empty();
  }
  std::printf("[   INFO   ] 1000 points: %zu inside an avoided area, %zu inside an object's footprint, "
              "%zu with fewer objects of the tag than k\n", inside_avoided, inside_object, short_lists);
  EXPECT_GT(inside_avoided, 10u);
  EXPECT_GT(inside_object, 50u);
  EXPECT_GT(short_lists, 10u);  // the search past the border ran too
}

TEST_F(SceneStoreTest, ListWithinIsExactAndTagFiltered) {
  SceneStore store(*c_);
  const Point p{7.5, 3};
  for (double r : {0.0, 1.0, 3.0, 6.5, 30.0}) {
    std::vector<NearObject> want;
    for (const NearObject& o : nearest_objects(scene_, p, "", 1000))
      if (o.distance <= r) want.push_back(o);
    expect_same_nearest(store.list(kMap, {.tag = "", .centre = p, .radius = r}), want, "radius " + std::to_string(r));
  }
  const auto chairs = store.list(kMap, {.tag = "chair"});
  EXPECT_EQ(chairs.size(), 4u);
  for (const ObjectRow& o : chairs) {
    EXPECT_EQ(o.tag_class, "interactable");
    EXPECT_EQ(o.source, "imported");
    EXPECT_TRUE(o.expires_at.empty());
  }
  EXPECT_EQ(store.list(kMap).size(), scene_.objects.size());
  EXPECT_THROW(store.list("ss_no_such_map"), MapNotFound);
}

TEST_F(SceneStoreTest, FailedImportsChangeNothing) {
  SceneStore store(*c_);
  store.expire_observations("2999-01-01 00:00:00");  // other tests' robots' SetObject observations
  const std::string before = fingerprint();
  // Without replace, a stored key is an error.
  EXPECT_THROW(store.import(kMap, scene_, {}), SceneKeyExists);
  // A bad polygon deep in the scene, an unknown tag, a duplicate key: refused, nothing stored.
  Scene bad = scene_;
  bad.objects[12].elements[0].footprint = {{0, 0}, {1, 1}, {1, 0}, {0, 1}};  // bow tie
  EXPECT_THROW(store.import(kMap, bad, {.replace = true}), std::invalid_argument);
  bad = scene_;
  bad.objects.back().tag = "ss_unknown_tag";
  EXPECT_THROW(store.import(kMap, bad, {.replace = true}), UnknownTag);
  bad = scene_;
  bad.objects.push_back(bad.objects.front());
  EXPECT_THROW(store.import(kMap, bad, {.replace = true}), std::invalid_argument);
  EXPECT_THROW(store.import("ss_no_such_map", scene_, {}), MapNotFound);
  EXPECT_EQ(fingerprint(), before);
  // A failure after replace deleted the old objects: an object key that a robot's
  // observation holds. The transaction takes the deletes back.
  execute(*admin(), "INSERT IGNORE INTO robots (db_user) VALUES ('ss_r1')");
  const unsigned robot = static_cast<unsigned>(scalar("SELECT id FROM robots WHERE db_user = 'ss_r1'"));
  const unsigned mid = static_cast<unsigned>(scalar(std::string("SELECT id FROM maps WHERE name = '") + kMap + "'"));
  const Observation seen = SceneStore(*connect_as(Role::Server)).record_observation(mid, robot, {3, 3}, "chair");
  const std::string with_observation = fingerprint();
  bad = scene_;
  bad.objects.back().id = seen.key;
  EXPECT_THROW(store.import(kMap, bad, {.replace = true}), SceneKeyExists);
  EXPECT_EQ(fingerprint(), with_observation);
  EXPECT_EQ(store.load(kMap), scene_);
  store.expire_observations("2999-01-01 00:00:00");
  EXPECT_EQ(fingerprint(), before);
}

TEST_F(SceneStoreTest, ReplaceKeepsObservationsAndAddTagsExtendsTheVocabulary) {
  SceneStore store(*c_);
  execute(*admin(), "INSERT IGNORE INTO robots (db_user) VALUES ('ss_r1')");
  execute(*admin(), "DELETE FROM tags WHERE tag = 'ss_lamp'");  // left by an earlier run
  const unsigned robot = static_cast<unsigned>(scalar("SELECT id FROM robots WHERE db_user = 'ss_r1'"));
  const unsigned mid = static_cast<unsigned>(scalar(std::string("SELECT id FROM maps WHERE name = '") + kMap + "'"));
  const Observation seen = store.record_observation(mid, robot, {3, 3}, "chair");
  Scene smaller = scene_;
  smaller.objects.resize(5);
  smaller.objects.push_back({.id = "ss-lamp", .tag = "ss_lamp", .elements = {{.footprint = {{6, 6}, {6.3, 6}, {6.3, 6.3}}}}});
  EXPECT_THROW(store.import(kMap, smaller, {.replace = true}), UnknownTag);
  const SceneImportReport r = store.import(kMap, smaller, {.replace = true, .add_tags = true});
  EXPECT_EQ(r.replaced_objects, scene_.objects.size());
  EXPECT_EQ(r.tags_added, std::vector<std::string>{"ss_lamp"});
  EXPECT_EQ(store.load(kMap), smaller);
  const auto all = store.list(kMap);
  EXPECT_EQ(all.size(), smaller.objects.size() + 1);  // the observation stays
  bool found = false;
  for (const ObjectRow& o : all) found = found || (o.key == seen.key && o.source == "observed");
  EXPECT_TRUE(found);
  // The added tag is an obstacle until an operator says otherwise.
  std::string cls;
  for (const TagInfo& t : store.tags()) {
    if (t.tag == "ss_lamp") cls = t.tag_class;
  }
  EXPECT_EQ(cls, "obstacle");
  EXPECT_FALSE(store.set_tag("ss_lamp", "landmark", std::string("a lamp")));
  for (const TagInfo& t : store.tags()) {
    if (t.tag == "ss_lamp") {
      EXPECT_EQ(t, (TagInfo{"ss_lamp", "landmark", "a lamp"}));
    }
  }
  EXPECT_THROW(store.set_tag("ss_lamp", "furniture", std::nullopt), std::invalid_argument);
  EXPECT_THROW(store.set_tag("a:b", "obstacle", std::nullopt), std::invalid_argument);
  // A tag in use cannot be deleted from under its objects.
  EXPECT_THROW(execute(*c_, "DELETE FROM tags WHERE tag = 'ss_lamp'"), mysqlpp::BadQuery);
  store.import(kMap, scene_, {.replace = true});
  store.expire_observations("2999-01-01 00:00:00");
}

TEST_F(SceneStoreTest, AvoidedAreasFromWkt) {
  SceneStore store(*c_);
  EXPECT_EQ(store.add_avoided_area(kMap, "polygon (( 6 6, 7 6, 7 7, 6 7, 6 6 ))"), "avoid-11");
  EXPECT_EQ(store.add_avoided_area(kMap, "POLYGON((6 8,7 8,6.5 9))", "ss-tri"), "ss-tri");
  EXPECT_THROW(store.add_avoided_area(kMap, "POLYGON((6 8,7 8,6.5 9))", "ss-tri"), SceneKeyExists);
  EXPECT_EQ(store.avoided_areas_containing(kMap, {6.5, 6.5}), std::vector<std::string>{"avoid-11"});
  EXPECT_EQ(store.avoided_areas_containing(kMap, {7, 6.5}), std::vector<std::string>{"avoid-11"});  // on the outline
  EXPECT_EQ(store.avoided_areas_containing(kMap, {6.5, 8.5}), std::vector<std::string>{"ss-tri"});
  for (const char* bad : {"POLYGON((0 0,1 1,1 0,0 1))", "POLYGON((0 0,1 0))", "LINESTRING(0 0,1 1)",
                          "POLYGON((0 0,1 0,1 1,0 0),(0.1 0.1,0.2 0.1,0.2 0.2,0.1 0.1))", "POLYGON((0 0,1 0,1 x))",
                          "POLYGON((0 0,1 0,1 1))x", "POLYGON((0 0,1 0,0 0))"}) {
    EXPECT_THROW(store.add_avoided_area(kMap, bad), std::invalid_argument) << bad;
  }
  EXPECT_TRUE(store.remove_avoided_area(kMap, "ss-tri"));
  EXPECT_FALSE(store.remove_avoided_area(kMap, "ss-tri"));
  EXPECT_EQ(parse_polygon_wkt(polygon_to_wkt({{0.1, 0.30000000000000004}, {2, 0}, {2, 2}})),
            (Polygon{{0.1, 0.30000000000000004}, {2, 0}, {2, 2}}));
}

// A map with many objects: the index is used, and it finds what a full scan finds.
TEST(SceneStoreIndex, ExplainShowsTheSpatialIndexAndItAgreesWithAFullScan) {
  const std::string map = "ss_many";
  ensure_map(map);
  auto c = connect_as(Role::Operator);
  SceneStore store(*c);
  Scene scene;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-100, 100), side(0.1, 1.5), yaw(0, 3.14159);
  const char* tags[] = {"box", "chair", "door", "plant"};
  for (int i = 0; i < 5000; ++i)
    scene.objects.push_back({.id = "o" + std::to_string(i), .tag = tags[i % 4],
                             .elements = {{.footprint = rectangle_footprint({u(rng), u(rng)}, side(rng), side(rng), yaw(rng))}}});
  store.import(map, scene, {.replace = true});
  EXPECT_EQ(store.near_index(map, {1, 2}, "door", 4), "sx_object_elements_footprint");
  EXPECT_EQ(store.near_index(map, {1, 2}, "", 0.5), "sx_object_elements_footprint");
  // The inspector's view query as docs/semantic-layer.md writes it uses it too.
  auto a = admin();
  mysqlpp::Query q = a->query(
      "EXPLAIN SELECT object_key, MIN(polygon_distance(footprint, POINT(1, 2))) AS d FROM v_object_elements"
      " WHERE map = 'ss_many' AND tag = 'door'"
      " AND MBRIntersects(footprint, ST_GeomFromText('POLYGON((-9 -8,11 -8,11 12,-9 12,-9 -8))'))"
      " GROUP BY object_key HAVING d <= 10 ORDER BY d");
  std::string key;
  for (const mysqlpp::Row& r : q.store())
    if (std::string(r["table"]) == "e") key = r["key"].is_null() ? "" : std::string(r["key"]);
  EXPECT_EQ(key, "sx_object_elements_footprint");

  std::uniform_real_distribution<double> wide(-130, 130);
  for (int i = 0; i < 40; ++i) {
    const Point p{wide(rng), wide(rng)};
    const std::string tag = i % 5 == 4 ? "" : tags[i % 4];
    NearStats st;
    const auto indexed = store.near(map, p, tag, 1 + i % 7, NearAccess::SpatialIndex, &st);
    const auto scanned = store.near(map, p, tag, 1 + i % 7, NearAccess::FullScan);
    ASSERT_EQ(indexed.size(), scanned.size());
    for (size_t k = 0; k < indexed.size(); ++k) {
      EXPECT_EQ(indexed[k].key, scanned[k].key) << i;
      EXPECT_EQ(*indexed[k].distance, *scanned[k].distance) << i;
    }
    const auto want = nearest_objects(scene, p, tag, 1 + i % 7);
    expect_same_nearest(indexed, want, "point " + std::to_string(i));
  }
}

TEST_F(SceneStoreTest, ObservationsAreRefreshedWhenSeenAgainAndExpire) {
  auto server = connect_as(Role::Server);  // SetObject writes with the server's account
  SceneStore store(*server);
  auto a = admin();
  execute(*a, "INSERT IGNORE INTO robots (db_user) VALUES ('ss_r1'), ('ss_r2')");
  const unsigned r1 = static_cast<unsigned>(scalar("SELECT id FROM robots WHERE db_user = 'ss_r1'"));
  const unsigned r2 = static_cast<unsigned>(scalar("SELECT id FROM robots WHERE db_user = 'ss_r2'"));
  const unsigned mid = static_cast<unsigned>(scalar(std::string("SELECT id FROM maps WHERE name = '") + kMap + "'"));
  store.expire_observations("2999-01-01 00:00:00");  // none left from other tests
  const std::string t0 = text(*a, "SELECT NOW(6)");
  auto at = [&](int seconds) { return text(*a, "SELECT TIMESTAMPADD(SECOND, " + std::to_string(seconds) + ", '" + t0 + "')"); };

  const Observation first = store.record_observation(mid, r1, {3, 3}, "chair", 60, t0);
  EXPECT_FALSE(first.refreshed);
  EXPECT_EQ(first.key, "ss_r1/chair/" + std::to_string(first.object_id));
  // Same robot, same name, 0.5 m away: the same chair, moved.
  const Observation again = store.record_observation(mid, r1, {3.5, 3}, "chair", 60, at(30));
  EXPECT_TRUE(again.refreshed);
  EXPECT_EQ(again.object_id, first.object_id);
  // Another robot, another name, or far away: new objects.
  EXPECT_FALSE(store.record_observation(mid, r2, {3.5, 3}, "chair", 60, t0).refreshed);
  EXPECT_FALSE(store.record_observation(mid, r1, {3.5, 3}, "Chair", 60, t0).refreshed);
  const Observation far = store.record_observation(mid, r1, {9, 9}, "chair", 60, t0);
  EXPECT_FALSE(far.refreshed);
  const Observation odd = store.record_observation(mid, r1, {12, 12}, "ss-teapot", 60, t0);

  SceneStore op(*c_);
  std::vector<ObjectRow> seen;
  for (const ObjectRow& o : op.list(kMap)) {
    if (o.source == "observed") seen.push_back(o);
  }
  ASSERT_EQ(seen.size(), 5u);
  for (const ObjectRow& o : seen) {
    EXPECT_TRUE(o.dynamic);
    EXPECT_FALSE(o.expires_at.empty());
    if (o.id == odd.object_id) {
      EXPECT_EQ(o.tag, "unknown");
      EXPECT_EQ(o.label, "ss-teapot");
    }
    if (o.id == first.object_id) {
      EXPECT_EQ(o.seen_at, at(30));
      EXPECT_EQ(o.expires_at, at(90));
      EXPECT_EQ(o.robot, "ss_r1");
    }
  }
  // The refreshed chair sits where it was seen last: 0.1 m from its centre to the edge.
  const auto near = op.near(kMap, {3.5, 3}, "chair", 1);
  ASSERT_EQ(near.size(), 1u);
  EXPECT_EQ(*near[0].distance, 0);
  EXPECT_NEAR(*op.near(kMap, {3.5, 3.6}, "chair", 1)[0].distance, 0.5, 1e-12);
  // The export holds imported objects only.
  EXPECT_EQ(op.load(kMap), scene_);

  EXPECT_EQ(store.expire_observations(at(59)), 0u);
  EXPECT_EQ(store.expire_observations(at(60)), 4u);  // all but the refreshed chair
  EXPECT_EQ(store.expire_observations(at(89)), 0u);
  EXPECT_EQ(store.expire_observations(at(90)), 1u);
  // Past its time an observation is gone for readers before the sweep too.
  store.record_observation(mid, r1, {3, 3}, "chair", 60, at(-600));
  EXPECT_EQ(op.list(kMap).size(), scene_.objects.size());
  EXPECT_EQ(store.expire_observations(), 1u);
  // The server cannot change the vocabulary, the scene or the avoided areas.
  EXPECT_THROW(store.set_tag("ss_x", "obstacle", std::nullopt), mysqlpp::BadQuery);
  EXPECT_THROW(store.add_avoided_area(kMap, "POLYGON((0 0,1 0,1 1))"), mysqlpp::BadQuery);
}

// The SQL of docs/semantic-layer.md ("## Database"), run as the inspector.
constexpr const char* kDoorsNear =
    "SELECT object_key, MIN(polygon_distance(footprint, POINT(7.5, 3))) AS d FROM v_object_elements"
    " WHERE map = 'ss_room' AND tag = 'door'"
    " AND MBRIntersects(footprint, ST_GeomFromText('POLYGON((-2.5 -7,17.5 -7,17.5 13,-2.5 13,-2.5 -7))'))"
    " GROUP BY object_key HAVING d <= 10 ORDER BY d, object_key";
constexpr const char* kAvoidedAt =
    "SELECT area_key FROM v_avoided_areas WHERE map = 'ss_room'"
    " AND MBRContains(area, POINT(2.5, 10.5)) AND ST_Intersects(area, POINT(2.5, 10.5))";
constexpr const char* kRecentDynamic =
    "SELECT object_key, tag, robot, label, seen_at, footprint_wkt"
    " FROM v_objects WHERE map = 'ss_room' AND source = 'observed' AND seen_at >= NOW(6) - INTERVAL 5 MINUTE"
    " ORDER BY seen_at DESC";

TEST_F(SceneStoreTest, InspectorRunsTheDocumentedQueriesAndWritesNothing) {
  auto inspector = connect(tcp_settings(Role::Inspector));
  const std::string mid = std::to_string(scalar(std::string("SELECT id FROM maps WHERE name = '") + kMap + "'"));
  for (const char* tag : {"door", "chair"}) {
    std::string sql = kDoorsNear;
    sql.replace(sql.find("'door'"), 6, std::string("'") + tag + "'");
    mysqlpp::Query q = inspector->query(sql);
    std::vector<ObjectRow> got;
    for (const mysqlpp::Row& r : q.store()) got.push_back({.key = std::string(r[0]), .distance = std::stod(std::string(r[1]))});
    std::vector<NearObject> want;
    for (const NearObject& o : nearest_objects(scene_, {7.5, 3}, tag, 100))
      if (o.distance <= 10) want.push_back(o);
    ASSERT_FALSE(want.empty());
    expect_same_nearest(got, want, tag);
  }
  {
    mysqlpp::Query q = inspector->query(kAvoidedAt);
    std::vector<std::string> got;
    for (const mysqlpp::Row& r : q.store()) got.push_back(std::string(r[0]));
    EXPECT_EQ(got, containing_avoided_areas(scene_, {2.5, 10.5}));
    EXPECT_EQ(got, std::vector<std::string>{"keepout-1"});
  }
  {
    auto server_conn = connect_as(Role::Server);
    SceneStore server(*server_conn);
    execute(*admin(), "INSERT IGNORE INTO robots (db_user) VALUES ('ss_r1')");
    const unsigned r1 = static_cast<unsigned>(scalar("SELECT id FROM robots WHERE db_user = 'ss_r1'"));
    server.expire_observations("2999-01-01 00:00:00");
    auto a = admin();
    server.record_observation(std::stoul(mid), r1, {4, 4}, "trolley", 600, text(*a, "SELECT NOW(6) - INTERVAL 10 MINUTE + INTERVAL 1 SECOND"));
    server.record_observation(std::stoul(mid), r1, {6, 4}, "box", 600, text(*a, "SELECT NOW(6) - INTERVAL 2 MINUTE"));
    server.record_observation(std::stoul(mid), r1, {8, 4}, "cat", 600, text(*a, "SELECT NOW(6) - INTERVAL 1 MINUTE"));
    mysqlpp::Query q = inspector->query(kRecentDynamic);
    std::vector<std::string> got;
    for (const mysqlpp::Row& r : q.store()) got.push_back(std::string(r[1]) + " " + std::string(r[3]));
    EXPECT_EQ(got, (std::vector<std::string>{"unknown cat", "box box"}));
    server.expire_observations("2999-01-01 00:00:00");
  }
  // Every view reads; the objects view has the class and the footprints.
  for (const char* v : {"v_tags", "v_objects", "v_object_elements", "v_avoided_areas", "v_map_bounds"}) {
    mysqlpp::Query q = inspector->query(std::string("SELECT * FROM ") + v + " LIMIT 1");
    EXPECT_NO_THROW(q.store()) << v;
  }
  EXPECT_EQ(text(*inspector, "SELECT CONCAT(class, ' ', elements, ' ', footprint_wkt) FROM v_objects"
                             " WHERE map = 'ss_room' AND object_key = 'door-1'"),
            "landmark 1 MULTIPOLYGON(((7 -0.2,8 -0.2,8 0,7 0,7 -0.2)))");
  EXPECT_EQ(text(*inspector, "SELECT JSON_VALUE(footprint_geojson, '$.type') FROM v_objects"
                             " WHERE map = 'ss_room' AND object_key = 'big-table'"),
            "MultiPolygon");
  EXPECT_EQ(text(*inspector, "SELECT bounds_wkt FROM v_map_bounds WHERE map = 'ss_room'"),
            "POLYGON((-0.2 -0.2,15.2 -0.2,15.2 15.2,-0.2 15.2,-0.2 -0.2))");
  const std::string before = fingerprint();
  for (const char* sql : {"SELECT * FROM env_objects LIMIT 1", "SELECT * FROM object_elements LIMIT 1",
                          "SELECT * FROM avoided_areas LIMIT 1", "SELECT * FROM tags LIMIT 1",
                          "DELETE FROM v_objects", "DELETE FROM v_avoided_areas", "UPDATE v_tags SET class = 'dynamic'",
                          "INSERT INTO tags (tag, class) VALUES ('x', 'obstacle')", "DELETE FROM env_objects",
                          "UPDATE object_elements SET zmin = 0"}) {
    mysqlpp::Query q = inspector->query(sql);
    EXPECT_THROW(q.execute(), mysqlpp::BadQuery) << sql;
  }
  EXPECT_EQ(fingerprint(), before);
  // Robots get nothing of the semantic layer.
  auto a = admin();
  mysqlpp::Query grants = a->query("SHOW GRANTS FOR fleetmap_robot_role");
  for (const mysqlpp::Row& r : grants.store()) {
    const std::string g(r[0]);
    for (const char* t : {"tags", "env_objects", "object_elements", "avoided_areas", "map_bounds", "v_objects"})
      EXPECT_EQ(g.find(std::string("`") + t + "`"), std::string::npos) << g;
  }
}

}  // namespace
}  // namespace fleetmap::test
