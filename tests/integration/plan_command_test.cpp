// `fleetmap plan` (server/cli/plan_command.h) through the real program: on a stored map and on
// a map file, its output format, and its exit codes.
#include <gtest/gtest.h>

#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include "common/geometry/geometry.h"
#include "tests/integration/test_db.h"

namespace fleetmap::test {
namespace {

struct Printed {
  std::vector<Point> waypoints;
  double length = -1;
};

// "x y" lines, then "length L".
Printed parse(const std::string& out) {
  Printed p;
  std::istringstream in(out);
  std::string line;
  while (std::getline(in, line)) {
    double x, y;
    if (std::sscanf(line.c_str(), "length %lf", &p.length) == 1) continue;
    if (std::sscanf(line.c_str(), "%lf %lf", &x, &y) == 2) p.waypoints.push_back({x, y});
  }
  return p;
}

TEST(PlanCommand, StoredMapAndFileGiveTheSamePath) {
  const std::string file = source_path("maps/example-campus.map");
  ASSERT_EQ(run("fleetmap", "map import " + file + " --name it_plan --replace").exit_code, 0);
  // Round the stairs of obstacle 6 (x 44..50, y 18.5..20) from below to above.
  const RunResult stored = run("fleetmap", "plan it_plan 47 17 47 21.5 --radius 0.5 --seed 3");
  ASSERT_EQ(stored.exit_code, 0) << stored.err;
  const Printed p = parse(stored.out);
  ASSERT_GE(p.waypoints.size(), 3u) << stored.out;
  EXPECT_NEAR(p.waypoints.front().x, 47, 1e-9);
  EXPECT_NEAR(p.waypoints.back().y, 21.5, 1e-9);
  EXPECT_GT(p.length, 4.5);
  const RunResult from_file = run("fleetmap", "plan --file " + file + " 47 17 47 21.5 --radius 0.5 --seed 3");
  ASSERT_EQ(from_file.exit_code, 0) << from_file.err;
  EXPECT_EQ(from_file.out, stored.out);
  // A robot that climbs goes straight over them.
  const RunResult climb = run("fleetmap", "plan it_plan 47 17 47 21.5 --radius 0.5 --climb-stairs");
  ASSERT_EQ(climb.exit_code, 0) << climb.err;
  EXPECT_NEAR(parse(climb.out).length, 4.5, 1e-3);
}

TEST(PlanCommand, NoPathAndBlockedEndsExitWith3) {
  const std::string file = source_path("maps/example-campus.map");
  // Inside the closed lab building (obstacle 2, x 40..55, y 26..36).
  RunResult r = run("fleetmap", "plan --file " + file + " 1 1 45 30 --max-time 0.3");
  EXPECT_EQ(r.exit_code, 3);
  EXPECT_NE(r.err.find("no path found"), std::string::npos) << r.err;
  EXPECT_TRUE(r.out.empty());
  r = run("fleetmap", "plan --file " + file + " 5.1 30 1 1");
  EXPECT_EQ(r.exit_code, 3);
  EXPECT_NE(r.err.find("start (5.100, 30.000) is blocked"), std::string::npos) << r.err;
  r = run("fleetmap", "plan --file " + file + " 1 1 47 19.25");
  EXPECT_EQ(r.exit_code, 3);
  EXPECT_NE(r.err.find("stairs of obstacle 6"), std::string::npos) << r.err;
}

// The stored map's objects and avoided areas block (by body height), the same as
// a file with --objects; --no-objects plans on the segments alone.
TEST(PlanCommand, ObjectsAndAvoidedAreasBlock) {
  const std::string map = source_path("maps/example-room.map"), objects = source_path("maps/example-room.geojson");
  ASSERT_EQ(run("fleetmap", "map import " + map + " --name it_plan_room --replace --drop all").exit_code, 0);
  ASSERT_EQ(run("fleetmap", "objects import it_plan_room " + objects).exit_code, 0);
  // Straight through the L-shaped keep-out zone (x 2..4, y 9..12) without the scene.
  RunResult bare = run("fleetmap", "plan it_plan_room 1 10.5 5 10.5 --radius 0.25 --no-objects");
  ASSERT_EQ(bare.exit_code, 0) << bare.err;
  EXPECT_NEAR(parse(bare.out).length, 4, 1e-9);
  const RunResult stored = run("fleetmap", "plan it_plan_room 1 10.5 5 10.5 --radius 0.25");
  ASSERT_EQ(stored.exit_code, 0) << stored.err;
  EXPECT_GT(parse(stored.out).length, 5);
  const RunResult file = run("fleetmap", "plan --file " + map + " --objects " + objects + " 1 10.5 5 10.5 --radius 0.25");
  ASSERT_EQ(file.exit_code, 0) << file.err;
  EXPECT_EQ(file.out, stored.out);
  // Deep inside the keep-out zone, and under the big table's top for a 1 m body.
  RunResult r = run("fleetmap", "plan it_plan_room 1 10.5 2.5 11 --radius 0.25");
  EXPECT_EQ(r.exit_code, 3);
  EXPECT_NE(r.err.find("goal (2.500, 11.000) is blocked: it is inside avoid:keepout-1"), std::string::npos) << r.err;
  r = run("fleetmap", "plan it_plan_room 1 10.5 7.5 7.5 --radius 0.25");
  EXPECT_EQ(r.exit_code, 3);
  EXPECT_NE(r.err.find("inside object:table:big-table"), std::string::npos) << r.err;
  r = run("fleetmap", "plan it_plan_room 1 10.5 7.5 7.5 --radius 0.25 --body-height 0.5");  // under the top
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(run("fleetmap", "plan it_plan_room 1 10.5 5 10.5 --objects " + objects).exit_code, 2);  // only with --file
}

TEST(PlanCommand, BadInputAndUsage) {
  const std::string file = source_path("maps/example-campus.map");
  EXPECT_EQ(run("fleetmap", "plan --file " + file + " 1 1 abc 3").exit_code, 2);
  EXPECT_EQ(run("fleetmap", "plan --file " + temp_path("missing.map") + " 1 1 3 3").exit_code, 1);  // I/O
  EXPECT_EQ(run("fleetmap", "plan --file " + file + " 1 1 3").exit_code, 64);
  EXPECT_EQ(run("fleetmap", "plan --file " + file + " name 1 1 3 3").exit_code, 64);
  EXPECT_EQ(run("fleetmap", "plan it_no_such_map 1 1 3 3").exit_code, 4);
}

TEST(PlanCommand, DrawsTheMapAndPath) {
  const std::string svg = temp_path("plan.svg");
  const RunResult r =
      run("fleetmap", "plan --file " + real_map("GDC1.vectormap.txt") + " 43.8 -11.28 1.21 25.49 --svg " + svg);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string text = read_file(svg);
  EXPECT_NE(text.find("<svg"), std::string::npos);
  EXPECT_NE(text.find("planned path"), std::string::npos);
}

}  // namespace
}  // namespace fleetmap::test
