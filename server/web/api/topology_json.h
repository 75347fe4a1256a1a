#pragma once
// A topological graph (SPEC 7, seed 003) as the API shows it and finds goals in it:
//
//   {"nodes":[{"id","name","type","x","y"}],"edges":[{"from","to","type"}]}
//
// Nodes carry no type of their own (the AMRL graphs have none); seed 003 places them
// where the edge type changes ("in front of every door"), so a node's type is the most
// telling type of its edges: stairs, elevator, door, room, corridor in that order (a node
// with a door edge is a door node). A node without edges has type null. name is null
// when the node has none.
#include <optional>
#include <string>
#include <unordered_map>

#include <nlohmann/json.hpp>

#include "common/planning/topo_graph.h"

namespace fleetmap::web {

// Every node's type as above, by node id; nodes without edges are not in it.
std::unordered_map<int, EdgeType> node_types(const TopoGraph& g);

nlohmann::json topology_json(const TopoGraph& g);

// The node a goal {"node": what} means: nodes named `what`, else nodes whose type is
// `what`; of several, the one nearest `near` (the robot's position; without one the first
// in graph order). nullptr when none matches.
const TopoNode* find_goal_node(const TopoGraph& g, const std::string& what, const std::optional<Point>& near);

}  // namespace fleetmap::web
