// A fleet connected at once (SPEC 4: every robot has its own account and connection;
// SPEC 5.3): 200 robots, more than MariaDB's default max_connections of 151, each holding
// its own connection to the private instance at the same time, each registered (Ready
// answered with its own Start) and each Alive taken by the real fleetmap-server and
// refreshing that robot's liveness. Bounded: a few seconds once the accounts exist.
#include <algorithm>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "tests/integration/server_fixture.h"
#include "tests/integration/test_db.h"

namespace fleetmap::test {
namespace {

constexpr int kFleet = 200;
constexpr const char* kMap = "fleet_conn_map";

std::string robot_name(int i) {
  char b[24];
  std::snprintf(b, sizeof b, "fleet_%03d", i);
  return b;
}

TEST(FleetConnections, TwoHundredRobotsConnectedAtOnceAreEachServed) {
  ensure_example_map(kMap);
  // The accounts through the account procedures (as `robot add`), on one connection.
  std::vector<std::string> names;
  for (int i = 0; i < kFleet; ++i) names.push_back(robot_name(i + 1));
  const std::vector<std::string> passwords = add_robots(names, kMap);

  ServerProcess server("", "fleet_connections_server.log");

  // All connected before any request: the instance must hold them all at once.
  std::vector<std::unique_ptr<SqlRobot>> robots;
  for (int i = 0; i < kFleet; ++i) {
    try {
      robots.push_back(std::make_unique<SqlRobot>(robot_name(i + 1), passwords[i]));
    } catch (const std::exception& e) {
      FAIL() << "robot " << i + 1 << " of " << kFleet << " could not connect: " << e.what();
    }
  }
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM information_schema.PROCESSLIST WHERE USER LIKE 'fleet\\_%'"), kFleet);

  // Ready: each robot gets its own Start, with its magic and its own robot id.
  for (int i = 0; i < kFleet; ++i) robots[i]->send("Ready", "{\"magic\": " + std::to_string(1000 + i) + "}");
  for (int i = 0; i < kFleet; ++i) {
    const std::vector<SqlAnswer> got = robots[i]->receive(2, std::chrono::seconds(20));
    ASSERT_EQ(got.size(), 2u) << robot_name(i + 1) << ": Start and SetMap expected";
    ASSERT_EQ(got[0].op, "Start") << robot_name(i + 1) << ": " << got[0].params.dump();
    EXPECT_EQ(got[0].params.value("magic", -1), 1000 + i) << robot_name(i + 1);
    EXPECT_EQ(got[0].params.value("robot_id", 0u),
              static_cast<unsigned>(scalar("SELECT id FROM robots WHERE db_user = '" + robot_name(i + 1) + "'")))
        << robot_name(i + 1);
    EXPECT_EQ(got[1].op, "SetMap") << robot_name(i + 1);
  }

  // Alive from all of them at once: each taken out of rr and each robot's liveness
  // refreshed after the send, none answered with an Error.
  const long long before_us = scalar("SELECT CAST(UNIX_TIMESTAMP(NOW(6)) * 1000000 AS UNSIGNED)");
  for (auto& r : robots) r->send("Alive");
  EXPECT_TRUE(wait_until(
      [] { return scalar("SELECT COUNT(*) FROM rr WHERE db_user LIKE 'fleet\\_%'") == 0; },
      std::chrono::seconds(20)))
      << scalar("SELECT COUNT(*) FROM rr") << " requests still waiting";
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM robots WHERE db_user LIKE 'fleet\\_%' AND removed_at IS NULL AND "
                   "last_seen >= FROM_UNIXTIME(" + std::to_string(before_us) + " / 1000000)"),
            kFleet);
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  for (int i = 0; i < kFleet; ++i) {
    const std::vector<SqlAnswer> rest = robots[i]->peek();
    EXPECT_TRUE(rest.empty()) << robot_name(i + 1) << " got " << rest.front().op << " " << rest.front().params.dump();
  }
  EXPECT_TRUE(server.running());
}

}  // namespace
}  // namespace fleetmap::test
