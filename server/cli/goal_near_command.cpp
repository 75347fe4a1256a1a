#include "server/cli/goal_near_command.h"

#include <cstdio>
#include <string>

#include "app/exit_codes.h"
#include "common/core/error.h"
#include "protocol/robot_whereabouts.h"
#include "server/core/goal_by_tag.h"
#include "server/core/goal_check.h"

namespace fleetmap {
namespace {

int fail(int code, const std::string& message) {
  std::fprintf(stderr, "fleetmap goal: %s\n", message.c_str());
  return code;
}

std::string point(Point p) {
  char b[64];
  std::snprintf(b, sizeof b, "(%.3f, %.3f)", p.x, p.y);
  return b;
}

}  // namespace

void add_goal_near_options(CLI::App& cmd, GoalNearArgs& args) {
  cmd.add_option("--near", args.tag, "go beside the nearest object with this tag (instead of X Y)");
  cmd.add_option("--map", args.map, "with --near: the map to look in (default and only choice: the robot's)");
  cmd.add_option("--margin", args.margin, "with --near: metres kept between the robot's disc and the object")
      ->check(CLI::Range(0.001, 100.0))
      ->capture_default_str();
}

int assign_goal_near(CliContext& ctx, const std::string& robot, const GoalNearArgs& args) {
  mysqlpp::Connection& c = ctx.connection();
  // --map before the search (which server/core/goal_by_tag.h shares with the web API):
  // the goal is in the robot's own map's frame, so naming another map is a mistake.
  if (!args.map.empty()) {
    const RobotWhereabouts w = robot_whereabouts(c, robot);  // RobotNotFound: exit 4
    refuse_if_lost(w, robot, "a goal beside " + args.tag);   // GoalRefused: exit 3
    if (args.map != w.map)
      throw BadInput("--map: robot '" + robot + "' works on map '" + w.map + "', not '" + args.map +
                     "'; its goals are in its own map's frame");
  }
  AcceptedGoalByTag g;
  try {
    g = accept_goal_by_tag(c, robot, args.tag, args.margin, planning_defaults(ctx.config_path()));
  } catch (const NoGoalByTag& e) {
    return fail(exit_code::kNotFound, e.what());
  } catch (const GoalByTagRefused& e) {
    return fail(exit_code::kNoPath, e.what());
  }
  std::printf("task %llu assigned to '%s': goal (%.3f, %.3f) beside %s '%s', %.3f m from it; path %.2f m from %s\n",
              g.task, robot.c_str(), g.goal.x, g.goal.y, g.tag.c_str(), g.object.c_str(), g.gap, g.path_length,
              point(g.from).c_str());
  return exit_code::kOk;
}

}  // namespace fleetmap
