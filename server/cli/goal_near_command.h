#pragma once
// `fleetmap goal ROBOT --near TAG [--map M] [--margin D]`: goals by meaning
// (docs/semantic-layer.md), through server/core/goal_by_tag.h (shared with the web API):
//
//   1. the robot's position: its last reported pose, else its initial pose (pose-ini);
//   2. the object with that tag nearest to it (SceneStore::near: live objects, by the
//      distance to their footprints);
//   3. a free point beside it, reachable with the planner GetPath uses for this robot
//      (its profile, the server's defaults; the map's live scene): choose_goal_beside,
//      common/planning/goal_near.h;
//   4. the usual goal: a task assigned, SetPosEnd pushed by the server.
//
// Exit codes: 0 assigned; 3 no free reachable point beside it (or the robot's position
// is blocked); 4 no such robot or map, no object with the tag, no known position.
#include <string>

#include <CLI/CLI.hpp>

#include "app/cli_context.h"

namespace fleetmap {

struct GoalNearArgs {
  std::string tag;    // --near
  std::string map;    // --map: where to look (default: the robot's map, which it must be)
  double margin = 0.1;  // metres beyond the robot's radius
};

void add_goal_near_options(CLI::App& cmd, GoalNearArgs& args);

// Steps 1-4; returns the exit code, with a message on standard error when not 0.
int assign_goal_near(CliContext& ctx, const std::string& robot, const GoalNearArgs& args);

}  // namespace fleetmap
