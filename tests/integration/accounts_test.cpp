// The accounts of SPEC 4: the inspector reads the views and nothing else.
#include <gtest/gtest.h>

#include "protocol/connection.h"
#include "tests/integration/test_db.h"

namespace fleetmap::test {
namespace {

// True when the statement runs; false when the server refuses it.
bool allowed(mysqlpp::Connection& c, const std::string& sql) {
  try {
    mysqlpp::Query q = c.query(sql);
    if (sql.rfind("SELECT", 0) == 0) q.store();
    else q.execute();
    return true;
  } catch (const mysqlpp::BadQuery&) {
    return false;
  }
}

class Inspector : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_EQ(run("fleetmap", "map import " + source_path("maps/example-campus.map") + " --name acc_example --replace")
                  .exit_code,
              0);
    // Over TCP with its password, as QGIS or the mariadb client would connect.
    c_ = connect(tcp_settings(Role::Inspector));
  }
  std::unique_ptr<mysqlpp::Connection> c_;
};

TEST_F(Inspector, ReadsTheViewsWithSpatialQueries) {
  mysqlpp::Query q = c_->query(
      "SELECT COUNT(*) FROM v_segments WHERE map = 'acc_example'"
      " AND MBRIntersects(geom, ST_GeomFromText('POLYGON((0 0,60 0,60 40,0 40,0 0))'))");
  EXPECT_GT(std::stoll(std::string(q.store()[0][0])), 10);
  for (const char* v : {"v_maps", "v_segments", "v_obstacles", "v_robot_status", "v_tasks", "v_trajectory_points",
                        "v_requests", "v_answers"})
    EXPECT_TRUE(allowed(*c_, std::string("SELECT * FROM ") + v + " LIMIT 1")) << v;
}

TEST_F(Inspector, SmallWindowQueriesOnTheSegmentViewMatchAFullScan) {
  // Small windows make the optimizer pick the spatial index: the case MDEV-26123 breaks
  // when the view reads another table first (sql/20_views.sql).
  ASSERT_EQ(run("fleetmap", "map import " + real_map("GDC1.vectormap.txt") + " --name acc_gdc1 --replace").exit_code, 0);
  const long long map_id = scalar("SELECT id FROM maps WHERE name = 'acc_gdc1'");
  size_t non_empty = 0;
  for (int i = 0; i < 30; ++i) {
    const double x = -40 + (i * 7919 % 80), y = -30 + (i * 104729 % 60), side = 1 + i % 5;
    const std::string poly = "ST_GeomFromText('POLYGON((" + std::to_string(x) + " " + std::to_string(y) + "," +
                             std::to_string(x + side) + " " + std::to_string(y) + "," + std::to_string(x + side) + " " +
                             std::to_string(y + side) + "," + std::to_string(x) + " " + std::to_string(y + side) + "," +
                             std::to_string(x) + " " + std::to_string(y) + "))')";
    mysqlpp::Query q = c_->query("SELECT COUNT(*) FROM v_segments WHERE map = 'acc_gdc1' AND MBRIntersects(geom, " + poly + ")");
    const long long via_view = std::stoll(std::string(q.store()[0][0]));
    const long long scanned = scalar("SELECT COUNT(*) FROM segments IGNORE INDEX (sx_segments_geom) WHERE map_id = " +
                                     std::to_string(map_id) + " AND MBRIntersects(geom, " + poly + ")");
    EXPECT_EQ(via_view, scanned) << poly;
    non_empty += scanned > 0;
  }
  EXPECT_GT(non_empty, 3u);
}

TEST_F(Inspector, CannotWriteAnythingNorReadBaseTables) {
  const long long segments = scalar("SELECT COUNT(*) FROM segments");
  for (const char* sql : {
           "SELECT * FROM segments LIMIT 1", "SELECT * FROM maps LIMIT 1", "SELECT * FROM rr LIMIT 1",
           "SELECT * FROM sa LIMIT 1", "SELECT * FROM sa_mine LIMIT 1", "SELECT * FROM mysql.user LIMIT 1",
           "INSERT INTO maps (name, mx1, my1, mx4, my4, border) VALUES ('x', 0, 1, 1, 0, POINT(0,0))",
           "INSERT INTO rr (op, params) VALUES ('Ready', '{}')",
           "UPDATE segments SET h = 0", "DELETE FROM segments",
           "UPDATE v_segments SET h = 0", "DELETE FROM v_segments", "DELETE FROM v_maps",
           "INSERT INTO v_tasks (robot, goal_x, goal_y) VALUES ('r', 0, 0)",
           "CREATE TABLE evil (x INT)", "DROP VIEW v_maps", "CREATE USER 'evil'@'%'",
       })
    EXPECT_FALSE(allowed(*c_, sql)) << sql;
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM segments"), segments);
}

TEST(Operator, ImportsMapsButCannotTouchProtocolTablesOrAccounts) {
  auto c = connect(tcp_settings(Role::Operator));
  EXPECT_TRUE(allowed(*c, "SELECT COUNT(*) FROM segments"));
  for (const char* sql : {"SELECT * FROM sa LIMIT 1", "DELETE FROM rr", "INSERT INTO sa (robot_id, db_user, op, params) "
                          "VALUES (1, 'r', 'Abort', '{}')", "CREATE USER 'evil'@'%'", "DROP TABLE segments"})
    EXPECT_FALSE(allowed(*c, sql)) << sql;
}

TEST(Accounts, NoAnonymousAccountsAndWrongPasswordsFail) {
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM mysql.user WHERE user = ''"), 0);
  DbSettings s = tcp_settings(Role::Inspector);
  s.password += "x";
  EXPECT_THROW(connect(s), DbError);
  s = tcp_settings(Role::Inspector);
  s.user = "nobody_here";
  EXPECT_THROW(connect(s), DbError);
}

}  // namespace
}  // namespace fleetmap::test
