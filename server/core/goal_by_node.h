#pragma once
// Goals at a place of the topological graph (SPEC 7, seed 003) for every front door:
// `fleetmap goal ROBOT --node WHAT` and the web API's POST /api/robots/{name}/goal
// {"node": WHAT}.
//
//   1. the robot's map and its graph (TopoStore), the robot's position: its last
//      reported pose, else its initial pose;
//   2. the node: the one named WHAT, else one whose type is WHAT (node_types); of
//      several, the nearest to the robot (without a position, the first in graph order);
//   3. the usual goal at the node's position: accept_goal (goal_check.h), refused at once
//      when the robot cannot reach it.
//
// What can go wrong, by class (app/exit_code_for.h gives the exit code):
//   RobotNotFound                 no such robot (4)
//   NotFound, TopoGraphNotFound   the robot has no map, its map has no graph (4)
//   NoGoalNode (a GoalRefused)    no node of that name or type (3; the API answers 404)
//   GoalRefused                   the robot is lost, the node unreachable (3; API 422)
// No task row is written unless the goal was accepted.
#include <optional>
#include <string>
#include <unordered_map>

#include <mysql++/mysql++.h>

#include "common/geometry/geometry.h"
#include "common/planning/topo_graph.h"
#include "server/core/goal_check.h"
#include "server/core/server_config.h"

namespace fleetmap {

class NoGoalNode : public GoalRefused {
 public:
  using GoalRefused::GoalRefused;
};

// Nodes carry no type of their own (the AMRL graphs have none); seed 003 places them
// where the edge type changes ("in front of every door"), so a node's type is the most
// telling type of its edges: stairs, elevator, door, room, corridor in that order (a node
// with a door edge is a door node). Nodes without edges are not in the map.
std::unordered_map<int, EdgeType> node_types(const TopoGraph& g);

// Step 2: nullptr when no node matches.
const TopoNode* find_goal_node(const TopoGraph& g, const std::string& what, const std::optional<Point>& near);

struct AcceptedGoalByNode {
  AcceptedGoal goal;
  TopoNode node;
};

// Steps 1-3: the robot, its map and graph read on `reads`, the goal given on `writes`
// (the web API reads with its own account and writes with the person's; the CLI passes
// one connection twice). Throws as the header comment says.
AcceptedGoalByNode accept_goal_by_node(mysqlpp::Connection& reads, mysqlpp::Connection& writes,
                                       const std::string& robot, const std::string& what, const ServerConfig& defaults);

}  // namespace fleetmap
