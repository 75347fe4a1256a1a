// How long the position history is kept ([server] history_keep_s,
// protocol/history_retention.h), against the real MariaDB and fleetmap-server:
//   * by default the server deletes no pose and no GPS fix, however old;
//   * with --history-keep 3600 it deletes those older than an hour and keeps the rest,
//     of every robot, on its housekeeping sweep;
//   * one call deletes at most its batch of each table, and the next calls the rest.
#include <gtest/gtest.h>

#include <thread>

#include "protocol/history_retention.h"
#include "tests/integration/server_fixture.h"
#include "tests/integration/test_db.h"

namespace fleetmap::test {
namespace {

constexpr const char* kMap = "hr_map";

class HistoryRetention : public ::testing::Test {
 protected:
  void SetUp() override {
    ensure_example_map(kMap);
    add_robot("hr_a", kMap);
    add_robot("hr_b", kMap);
    a_ = std::to_string(scalar("SELECT id FROM robots WHERE db_user = 'hr_a'"));
    b_ = std::to_string(scalar("SELECT id FROM robots WHERE db_user = 'hr_b'"));
    auto db = admin();
    // Old history of other robots (an instance kept from an earlier run) would share the
    // batches counted below.
    db->query("DELETE FROM trajectories WHERE t < SYSDATE(6) - INTERVAL 1 HOUR").execute();
    db->query("DELETE FROM gps_fixes WHERE t < SYSDATE(6) - INTERVAL 1 HOUR").execute();
    for (const std::string& id : {a_, b_}) {
      db->query("DELETE FROM trajectories WHERE robot_id = " + id).execute();
      db->query("DELETE FROM gps_fixes WHERE robot_id = " + id).execute();
    }
  }
  // n poses and n GPS fixes of the robot, `age` ago (an SQL interval, e.g. "2 HOUR").
  static void add_history(const std::string& robot, int n, const std::string& age) {
    auto db = admin();
    for (int i = 0; i < n; ++i) {
      const std::string t = "SYSDATE(6) - INTERVAL " + age + " - INTERVAL " + std::to_string(i) + " SECOND";
      db->query("INSERT INTO trajectories (robot_id, t, x, y, theta, v, w, pos) VALUES (" + robot + ", " + t + ", " +
                std::to_string(i) + ", 1, 0, 0, 0, Point(" + std::to_string(i) + ", 1))")
          .execute();
      db->query("INSERT INTO gps_fixes (robot_id, t, lat, lon) VALUES (" + robot + ", " + t + ", 30.28, -97.73)").execute();
    }
  }
  long long poses(const std::string& robot, const std::string& where = "TRUE") const {
    return scalar("SELECT COUNT(*) FROM trajectories WHERE robot_id = " + robot + " AND " + where);
  }
  long long fixes(const std::string& robot, const std::string& where = "TRUE") const {
    return scalar("SELECT COUNT(*) FROM gps_fixes WHERE robot_id = " + robot + " AND " + where);
  }
  std::string a_, b_;
};

constexpr const char* kOld = "t < SYSDATE(6) - INTERVAL 1 HOUR";

TEST_F(HistoryRetention, TheServerKeepsEverythingByDefaultAndOnlyTheRecentPastWhenTold) {
  add_history(a_, 3, "2 HOUR");
  add_history(a_, 2, "1 SECOND");
  add_history(b_, 4, "1 DAY");
  {
    ServerProcess server("", "hr_default.log");
    // The sweep runs on the first pass and every 2 s: two sweeps at least.
    std::this_thread::sleep_for(std::chrono::milliseconds(2500));
    ASSERT_TRUE(server.running());
  }
  EXPECT_EQ(poses(a_), 5);
  EXPECT_EQ(fixes(a_), 5);
  EXPECT_EQ(poses(b_), 4);

  ServerProcess server("--history-keep 3600", "hr_keep.log");
  EXPECT_TRUE(wait_until([&] { return poses(a_, kOld) + poses(b_, kOld) + fixes(a_, kOld) + fixes(b_, kOld) == 0; },
                         std::chrono::seconds(10)))
      << server.log().substr(0, 5000);
  EXPECT_EQ(poses(a_), 2);  // the recent ones stay
  EXPECT_EQ(fixes(a_), 2);
  EXPECT_EQ(poses(b_), 0);
  EXPECT_EQ(fixes(b_), 0);
}

TEST_F(HistoryRetention, ACallDeletesAtMostItsBatchOfEachTable) {
  add_history(a_, 7, "2 HOUR");
  add_history(b_, 5, "1 SECOND");
  auto db = admin();
  HistoryDeleted first = delete_history_before(*db, 3600, 4);
  EXPECT_EQ(first.trajectory_rows, 4u);
  EXPECT_EQ(first.gps_fixes, 4u);
  EXPECT_EQ(poses(a_), 3);
  HistoryDeleted second = delete_history_before(*db, 3600, 4);
  EXPECT_EQ(second.trajectory_rows, 3u);
  EXPECT_EQ(second.gps_fixes, 3u);
  EXPECT_EQ(delete_history_before(*db, 3600, 4).trajectory_rows, 0u);
  EXPECT_EQ(poses(a_), 0);
  EXPECT_EQ(poses(b_), 5);
  EXPECT_EQ(fixes(b_), 5);
  // 0 keeps everything: even a pose of a day ago stays.
  add_history(b_, 1, "1 DAY");
  EXPECT_EQ(delete_history_before(*db, 0).trajectory_rows, 0u);
  // Nor does a keep too long to count in microseconds (an overflow would put the cutoff
  // in the future and delete every pose).
  EXPECT_EQ(delete_history_before(*db, 1e300).trajectory_rows, 0u);
  EXPECT_EQ(poses(b_), 6);
}

}  // namespace
}  // namespace fleetmap::test
