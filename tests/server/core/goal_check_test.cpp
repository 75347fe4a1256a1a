// The goal check every front door shares (server/core/goal_check.h), on a planner built
// here the way the server builds one: refusals for a goal outside the border, in an
// obstacle, in an avoided area, behind a gap too narrow for the robot's radius; what is
// accepted, and what is checked without a known position. The gap's width and the
// obstacles' places are written out below, so the expected verdicts are by hand.
#include "server/core/goal_check.h"

#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "common/io/seed_format.h"
#include "common/planning/planning_scene.h"

namespace fleetmap {
namespace {

// 20 m x 10 m. A wall at x 9.9..10.1 from y 0 to 4.5 and from 5.5 to 10: a 1 m gap, which
// a disc of radius 0.3 passes (0.6 < 1) and one of radius 0.6 does not (1.2 > 1).
// A box at x 15..17, y 2..4.
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

struct GoalCheckTest : ::testing::Test {
  Map map = read_seed(kGapMap, "gap.map");
  Scene scene;
  GoalCheckTest() {
    map.compute_bounds();
    scene.avoided.push_back({"keepout", {{2, 7}, {4, 7}, {4, 9}, {2, 9}}});  // x 2..4, y 7..9
  }
  // The planner GetPath would use for a robot of this radius (PlannerCache's recipe).
  MapPlanner planner(double radius) const {
    const PlannerProfile profile{radius, 1.0, false};
    const PlannerOptions o = server_planner_options(profile);
    return MapPlanner(map, planning_obstacles(map, scene, profile.body_height, o.robot), o);
  }
  // The refusal's message, or "" when accepted.
  std::string refusal(double radius, std::optional<Point> from, Point goal) const {
    try {
      check_goal_on(planner(radius), map, "r1", "gap", from, goal);
    } catch (const GoalRefused& e) {
      return e.what();
    }
    return "";
  }
};

TEST_F(GoalCheckTest, AReachableGoalIsAcceptedWithAPathNoShorterThanTheStraightLine) {
  const GoalAcceptance a = check_goal_on(planner(0.3), map, "r1", "gap", Point{5, 5}, {15, 8});
  ASSERT_TRUE(a.from);
  EXPECT_EQ(a.from->x, 5);
  EXPECT_GE(a.path_length, std::hypot(10.0, 3.0) - 1e-9);
}

TEST_F(GoalCheckTest, AGoalOutsideTheMapIsRefusedNamingTheBorder) {
  const std::string m = refusal(0.3, Point{5, 5}, {500, 500});
  EXPECT_NE(m.find("goal (500.000, 500.000) for robot 'r1' refused"), std::string::npos) << m;
  EXPECT_NE(m.find("outside the map 'gap'"), std::string::npos) << m;
  EXPECT_NE(m.find("x 0..20, y 0..10"), std::string::npos) << m;
  // Also without a known position: where the goal is needs no start.
  EXPECT_NE(refusal(0.3, std::nullopt, {-1, 5}).find("outside the map"), std::string::npos);
}

TEST_F(GoalCheckTest, AGoalInsideAnObstacleIsRefused) {
  // The box's centre, 1 m from its walls: not near a segment, but closed in.
  const std::string m = refusal(0.3, Point{5, 5}, {16, 3});
  EXPECT_NE(m.find("it is inside obstacle 3 (box)"), std::string::npos) << m;
  EXPECT_NE(refusal(0.3, std::nullopt, {16, 3}).find("inside obstacle 3"), std::string::npos);
  // Just beside the box, closer than the radius: refused too; 0.5 m away: accepted.
  EXPECT_NE(refusal(0.3, Point{5, 5}, {17.2, 3}).find("within the robot's radius 0.3 m of obstacle 3"),
            std::string::npos);
  EXPECT_EQ(refusal(0.3, Point{5, 5}, {17.5, 3}), "");
}

TEST_F(GoalCheckTest, AGoalInAnAvoidedAreaIsRefusedNamingIt) {
  const std::string m = refusal(0.3, Point{5, 5}, {3, 8});
  EXPECT_NE(m.find("it is inside avoid:keepout"), std::string::npos) << m;
  EXPECT_NE(refusal(0.3, std::nullopt, {3, 8}).find("avoid:keepout"), std::string::npos);
}

TEST_F(GoalCheckTest, BehindAGapNarrowerThanItsDiameterTheGoalIsUnreachableForTheRobot) {
  EXPECT_EQ(refusal(0.3, Point{5, 5}, {15, 8}), "");
  const std::string m = refusal(0.6, Point{5, 5}, {15, 8});
  EXPECT_NE(m.find("no path from the robot's position (5.000, 5.000) for its radius 0.6 m"), std::string::npos) << m;
}

TEST_F(GoalCheckTest, ARobotStandingInAnObstacleCannotBeSentAnywhere) {
  const std::string m = refusal(0.3, Point{17.2, 3}, {5, 5});
  EXPECT_NE(m.find("the robot's position (17.200, 3.000) is blocked"), std::string::npos) << m;
}

TEST_F(GoalCheckTest, InsideTheSameClosedObstacleAsTheRobotAGoalIsPlanned) {
  // A robot inside the box (a closed room of the map) may move within it.
  EXPECT_EQ(refusal(0.3, Point{15.6, 2.6}, {16.4, 3.4}), "");
  ASSERT_NE(enclosing_obstacle(map, {16, 3}), nullptr);
  EXPECT_EQ(enclosing_obstacle(map, {16, 3})->id, 3);
  EXPECT_EQ(enclosing_obstacle(map, {12, 3}), nullptr);
}

TEST_F(GoalCheckTest, WithoutAKnownPositionOnlyTheGoalsPlaceIsChecked) {
  // Unreachable for 0.6 m, but with no start that cannot be known: accepted, unplanned.
  const GoalAcceptance a = check_goal_on(planner(0.6), map, "r1", "gap", std::nullopt, {15, 8});
  EXPECT_FALSE(a.from);
}

TEST(GoalCheck, ALostRobotIsRefusedOthersPass) {
  RobotWhereabouts w;
  w.state = RobotState::Lost;
  w.last_seen = "2026-12-01 10:00:00";
  try {
    refuse_if_lost(w, "r1", "goal (1, 2)");
    FAIL() << "a lost robot's goal must be refused";
  } catch (const GoalRefused& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("robot 'r1' refused: the robot is lost (silent since 2026-12-01 10:00:00)"), std::string::npos)
        << m;
  }
  // A robot whose localization lost its pose is refused too, saying why.
  w.state = RobotState::Localizing;
  try {
    refuse_if_lost(w, "r1", "goal (1, 2)");
    FAIL() << "a localizing robot's goal must be refused";
  } catch (const GoalRefused& e) {
    EXPECT_NE(std::string(e.what()).find("the robot is localizing"), std::string::npos) << e.what();
  }
  for (RobotState s : {RobotState::Offline, RobotState::Ready, RobotState::Moving, RobotState::Stopped}) {
    w.state = s;
    EXPECT_NO_THROW(refuse_if_lost(w, "r1", "goal (1, 2)"));
  }
}

TEST(GoalCheck, TheProfileFallsBackToTheServersDefaults) {
  ServerConfig defaults;
  defaults.robot_radius_m = 0.45;
  defaults.body_height_m = 1.7;
  RobotWhereabouts w;
  PlannerProfile p = planner_profile(w, defaults);
  EXPECT_EQ(p.radius, 0.45);
  EXPECT_EQ(p.body_height, 1.7);
  EXPECT_FALSE(p.can_climb_stairs);
  w.radius = 0.2;
  w.body_height = 0.5;
  w.can_stairs = true;
  p = planner_profile(w, defaults);
  EXPECT_EQ(p.radius, 0.2);
  EXPECT_EQ(p.body_height, 0.5);
  EXPECT_TRUE(p.can_climb_stairs);
}

// With the map's graph, a goal that whole-map RRT-Connect gives up on (here: one
// iteration allowed) is accepted when the graph reaches it: the gap's node is in sight of
// both ends, so no RRT leg is needed. Without the graph the same goal is refused.
TEST_F(GoalCheckTest, AGoalRrtGivesUpOnIsAcceptedThroughTheGraph) {
  const PlannerProfile profile{0.3, 1.0, false};
  PlannerOptions o = server_planner_options(profile);
  o.rrt.max_iterations = 1;
  o.attempts = 1;
  const MapPlanner weak(map, planning_obstacles(map, scene, profile.body_height, o.robot), o);
  TopoGraph g;
  g.add_node({1, {10, 5}, "gap"});
  const Point from{5, 2}, goal{15, 6};
  EXPECT_THROW(check_goal_on(weak, map, "r1", "gap", from, goal), GoalRefused);
  const GoalAcceptance a = check_goal_on(weak, map, "r1", "gap", from, goal, &g);
  ASSERT_TRUE(a.from);
  // Through the gap: at least the way via (10, 5) with the corners cut by the radius.
  EXPECT_GT(a.path_length, std::hypot(5, 3) + std::hypot(5, 1) - 0.7);
}

}  // namespace
}  // namespace fleetmap
