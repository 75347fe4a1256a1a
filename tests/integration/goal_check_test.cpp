// Honest goals through the real programs (server/core/goal_check.h): `fleetmap goal X Y`
// refuses at once, with exit 3 and no task row, a goal outside the map, inside an
// obstacle, in an avoided area, unreachable for the robot's profile, or for a lost robot;
// a goal GetPath cannot reach later fails its task with the reason, and the simulated
// robot stops instead of driving into the obstacle.
//
// The map is written here: 20 m x 10 m, a wall at x = 10 with a 1 m gap (y 4.5..5.5),
// which a robot of radius 0.3 m passes and one of 0.6 m does not, and a closed box at
// x 15..17, y 2..4.

#include <cmath>
#include <cstdlib>
#include <string>
#include <thread>

#include <gtest/gtest.h>

#include "tests/integration/server_fixture.h"
#include "tests/integration/test_db.h"

namespace fleetmap::test {
namespace {

constexpr const char* kGapMap =
    "border;\n0;10;\n20;0;\n#\n"
    "obstacle;\n1;1;4;wall,south;\n#\n"
    "9.9;0;\n10.1;0;\n2;0;wall;\n#\n10.1;0;\n10.1;4.5;\n2;0;wall;\n#\n"
    "10.1;4.5;\n9.9;4.5;\n2;0;wall;\n#\n9.9;4.5;\n9.9;0;\n2;0;wall;\n#\n"
    "obstacle;\n2;1;4;wall,north;\n#\n"
    "9.9;5.5;\n10.1;5.5;\n2;0;wall;\n#\n10.1;5.5;\n10.1;10;\n2;0;wall;\n#\n"
    "10.1;10;\n9.9;10;\n2;0;wall;\n#\n9.9;10;\n9.9;5.5;\n2;0;wall;\n#\n"
    "obstacle;\n3;1;4;box;\n#\n"
    "15;2;\n17;2;\n1;0;box;\n#\n17;2;\n17;4;\n1;0;box;\n#\n17;4;\n15;4;\n1;0;box;\n#\n15;4;\n15;2;\n1;0;box;\n#\n";

class GoalCheck : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    write_file(temp_path("gc_gap.map"), kGapMap);
    RunResult r = run("fleetmap", "map import " + temp_path("gc_gap.map") + " --name gc_gap --replace --drop all");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    r = run("fleetmap", "avoid add gc_gap --id keepout --wkt 'POLYGON((2 7, 4 7, 4 9, 2 9, 2 7))'");
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
  void SetUp() override {
    password_ = add_robot("gc_r1", "gc_gap");
    // A robot added again keeps its row: start from a known pose and the default profile.
    admin()->query("UPDATE robots SET x = 5, y = 5, ini_x = NULL, ini_y = NULL, radius = NULL, "
                   "body_height = NULL, state = 'offline' WHERE db_user = 'gc_r1'").execute();
    robot_id_ = std::to_string(scalar("SELECT id FROM robots WHERE db_user = 'gc_r1'"));
    admin()->query("DELETE FROM avoided_areas WHERE area_key = 'late'").execute();  // left by a failed run
  }
  long long tasks() { return scalar("SELECT COUNT(*) FROM tasks WHERE robot_id = " + robot_id_); }
  // `fleetmap goal gc_r1 X Y` refused: exit 3, no task, the message has `why`.
  void expect_refused(const std::string& xy, const std::string& why) {
    const long long before = tasks();
    const RunResult r = run("fleetmap", "goal gc_r1 " + xy);
    EXPECT_EQ(r.exit_code, 3) << xy << ": " << r.out << r.err;
    EXPECT_NE(r.err.find("refused"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(why), std::string::npos) << r.err;
    EXPECT_EQ(tasks(), before) << xy << ": no task may be created";
  }
  std::string password_, robot_id_;
};

TEST_F(GoalCheck, AReachableGoalIsAssignedWithItsPath) {
  const long long before = tasks();
  const RunResult r = run("fleetmap", "goal gc_r1 15 8");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("from (5.000, 5.000)"), std::string::npos) << r.out;
  EXPECT_EQ(tasks(), before + 1);
}

TEST_F(GoalCheck, OutsideTheMapIsRefusedWithExit3AndNoTask) {
  expect_refused("500 500", "outside the map 'gc_gap'");
}

TEST_F(GoalCheck, InsideAnObstacleIsRefused) { expect_refused("16 3", "inside obstacle 3 (box)"); }

TEST_F(GoalCheck, InAnAvoidedAreaIsRefused) { expect_refused("3 8", "inside avoid:keepout"); }

TEST_F(GoalCheck, UnreachableForTheRobotsProfileIsRefused) {
  ASSERT_EQ(run("fleetmap", "robot set gc_r1 --radius 0.6").exit_code, 0);
  expect_refused("15 8", "no path from the robot's position (5.000, 5.000) for its radius 0.6 m");
}

TEST_F(GoalCheck, ALostRobotsGoalIsRefusedNotQueued) {
  admin()->query("UPDATE robots SET state = 'lost' WHERE db_user = 'gc_r1'").execute();
  expect_refused("15 8", "the robot is lost");
}

TEST_F(GoalCheck, WithoutAKnownPositionTheGoalsPlaceIsCheckedAndTheOutputSaysSo) {
  admin()->query("UPDATE robots SET x = NULL, y = NULL WHERE db_user = 'gc_r1'").execute();
  expect_refused("3 8", "inside avoid:keepout");
  const RunResult r = run("fleetmap", "goal gc_r1 15 8");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("no known position"), std::string::npos) << r.out;
}

TEST_F(GoalCheck, ConnectionFlagsAfterTheSubcommandAreTheSameAsBefore) {
  const std::string conf = std::getenv("FLEETMAP_CONFIG");
  const RunResult before = run("fleetmap", "--config " + conf + " tasks --robot gc_r1 --limit 1");
  const RunResult after = run("fleetmap", "tasks --robot gc_r1 --limit 1 --config " + conf);
  ASSERT_EQ(after.exit_code, 0) << after.err;
  EXPECT_EQ(after.out, before.out);
  EXPECT_EQ(run("fleetmap", "tasks --config /no/such.conf").exit_code, 1);  // the flag is taken, not ignored
}

// The goal was fine when given; an avoided area drawn over it before the robot set off
// makes GetPath answer no_path: the task fails with the reason, and the robot stays.
TEST_F(GoalCheck, NoPathAtGetPathFailsTheTaskAndTheSimulatedRobotStops) {
  admin()->query("UPDATE robots SET x = NULL, y = NULL WHERE db_user = 'gc_r1'").execute();
  write_file(temp_path("gc_r1.pw"), password_ + "\n");
  ASSERT_EQ(run("fleetmap", "pose-ini gc_r1 5 5 0").exit_code, 0);
  ASSERT_EQ(run("fleetmap", "goal gc_r1 15 8").exit_code, 0);
  const std::string task = std::to_string(scalar("SELECT MAX(id) FROM tasks WHERE robot_id = " + robot_id_));
  ASSERT_EQ(run("fleetmap", "avoid add gc_gap --id late --wkt 'POLYGON((14 7, 16 7, 16 9, 14 9, 14 7))'").exit_code, 0);

  ServerProcess server("", "gc_server.log");
  RobotSimProcess robot("gc_r1", "--start 5 5 0 --particles 500 --tracking-particles 300 --seed 3");
  const bool failed = wait_until([&] { return scalar("SELECT state = 'failed' FROM tasks WHERE id = " + task) == 1; },
                                 std::chrono::seconds(20));
  EXPECT_EQ(run("fleetmap", "avoid remove gc_gap late").exit_code, 0);
  ASSERT_TRUE(failed) << robot.log() << server.log();
  auto c = admin();
  const std::string reason = std::string(c->query("SELECT reason FROM tasks WHERE id = " + task).store()[0][0]);
  EXPECT_NE(reason.find("no path to (15.000000, 8.000000)"), std::string::npos) << reason;
  EXPECT_NE(reason.find("avoid:late"), std::string::npos) << reason;
  // The robot said so, and reports Stopped where it started, well short of the goal.
  ASSERT_TRUE(wait_until([&] { return scalar("SELECT state = 'stopped' FROM robots WHERE id = " + robot_id_) == 1; }));
  std::this_thread::sleep_for(std::chrono::milliseconds(1500));
  EXPECT_LT(scalar("SELECT ROUND(100 * SQRT(POW(x - 5, 2) + POW(y - 5, 2))) FROM robots WHERE id = " + robot_id_), 50);
  EXPECT_NE(robot.log().find("GetPath refused (no_path)"), std::string::npos) << robot.log();
  // The operator sees it too.
  const RunResult t = run("fleetmap", "tasks --robot gc_r1 --limit 1 --json");
  ASSERT_EQ(t.exit_code, 0) << t.err;
  const auto j = nlohmann::json::parse(t.out);
  ASSERT_EQ(j.size(), 1u);
  EXPECT_EQ(j[0]["state"], "failed");
  EXPECT_EQ(j[0]["reason"], reason);
}

}  // namespace
}  // namespace fleetmap::test
