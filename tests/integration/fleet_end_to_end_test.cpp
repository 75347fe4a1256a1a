// The whole task life cycle with the real programs: fleetmap-server, four fleetmap-robot
// processes on GDC1 (each with its own account), operator goals and an abort.

#include <memory>
#include <thread>

#include <gtest/gtest.h>

#include "tests/integration/server_fixture.h"
#include "tests/integration/test_db.h"

namespace fleetmap::test {
namespace {

// A robot tracking from its true start pose (the operator's initial pose).
std::unique_ptr<RobotSimProcess> start_robot(const std::string& name, const std::string& start, int seed) {
  return std::make_unique<RobotSimProcess>(
      name, "--start " + start + " --speed 1.5 --tracking-particles 500 --seed " + std::to_string(seed));
}

std::string task_state(const std::string& robot) {
  auto c = admin();
  mysqlpp::Query q = c->query(
      "SELECT t.state FROM tasks t JOIN robots r ON r.id = t.robot_id WHERE r.db_user = '" + robot +
      "' ORDER BY t.id DESC LIMIT 1");
  auto r = q.store();
  return r.empty() ? "" : std::string(r[0][0]);
}

TEST(FleetEndToEnd, ThreeRobotsArriveAFourthIsAbortedAndStops) {
  ASSERT_TRUE(import_real_map_once("e2e_gdc1", "GDC1.vectormap.txt"));
  // name, true start pose = operator's initial pose, goal: along the upper wing's corridor
  const struct {
    std::string name, start;
    double gx, gy;
  } robots[] = {{"e2e_r1", "-24 8.6 0", -12, 8.6},
                {"e2e_r2", "30 8.8 3.14159", 18, 8.8},
                {"e2e_r3", "-5 8.5 0", 6, 8.6},
                {"e2e_r4", "10 8.6 3.14159", -20, 8.6}};
  for (const auto& r : robots) {
    add_robot(r.name, "e2e_gdc1");
    ASSERT_EQ(run("fleetmap", "pose-ini " + r.name + " " + r.start).exit_code, 0);
  }
  ServerProcess server("", "e2e_server.log");
  std::vector<std::unique_ptr<RobotSimProcess>> procs;
  int seed = 1;
  for (const auto& r : robots) procs.push_back(start_robot(r.name, r.start, seed++));

  // All four registered and reporting poses.
  auto reporting = [] {
    return scalar("SELECT COUNT(*) FROM robots WHERE db_user LIKE 'e2e_r%' AND removed_at IS NULL AND x IS NOT NULL");
  };
  for (int i = 0; i < 300 && reporting() < 4; ++i) std::this_thread::sleep_for(std::chrono::milliseconds(100));
  ASSERT_EQ(reporting(), 4) << procs[0]->log();

  for (const auto& r : robots)
    ASSERT_EQ(run("fleetmap", "goal " + r.name + " " + std::to_string(r.gx) + " " + std::to_string(r.gy)).exit_code, 0);
  // The fourth has 30 m to go: abort it on the way.
  for (int i = 0; i < 100 && task_state("e2e_r4") != "active"; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  EXPECT_EQ(task_state("e2e_r4"), "active");
  std::this_thread::sleep_for(std::chrono::seconds(3));
  ASSERT_EQ(run("fleetmap", "abort e2e_r4 --reason test").exit_code, 0);

  auto settled = [&] {
    for (int k = 0; k < 3; ++k)
      if (task_state(robots[k].name) != "done") return false;
    return task_state("e2e_r4") == "aborted";
  };
  for (int i = 0; i < 600 && !settled(); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(100));
  for (int k = 0; k < 3; ++k) EXPECT_EQ(task_state(robots[k].name), "done") << robots[k].name;
  EXPECT_EQ(task_state("e2e_r4"), "aborted");

  // The aborted robot stopped well before its goal, and stays stopped.
  std::this_thread::sleep_for(std::chrono::seconds(1));
  const long long x1 = scalar("SELECT ROUND(x * 100) FROM robots WHERE db_user = 'e2e_r4'");
  std::this_thread::sleep_for(std::chrono::seconds(2));
  EXPECT_EQ(scalar("SELECT ROUND(x * 100) FROM robots WHERE db_user = 'e2e_r4'"), x1);
  EXPECT_GT(x1, -2000 + 300);  // not at its goal x = -20
  EXPECT_EQ(scalar("SELECT state = 'stopped' FROM robots WHERE db_user = 'e2e_r4'"), 1);
  // Arrivals were reported near the goals.
  for (int k = 0; k < 3; ++k)
    EXPECT_LT(scalar("SELECT ROUND(100 * SQRT(POW(x - " + std::to_string(robots[k].gx) + ", 2) + POW(y - " +
                     std::to_string(robots[k].gy) + ", 2))) FROM robots WHERE db_user = '" + robots[k].name + "'"),
              60)
        << robots[k].name;
}

}  // namespace
}  // namespace fleetmap::test
