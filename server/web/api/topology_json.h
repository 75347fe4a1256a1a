#pragma once
// A topological graph (SPEC 7, seed 003) as the API shows it and finds goals in it:
//
//   {"nodes":[{"id","name","type","x","y"}],"edges":[{"from","to","type"}]}
//
// A node's type is its most telling edge type (server/core/goal_by_node.h, node_types);
// type null for a node without edges. name is null when the node has none.
#include <optional>
#include <string>
#include <unordered_map>

#include <nlohmann/json.hpp>

#include "common/planning/topo_graph.h"
#include "server/core/goal_by_node.h"

namespace fleetmap::web {

// Shared with the CLI (`fleetmap goal --node`): server/core/goal_by_node.h.
using fleetmap::find_goal_node;
using fleetmap::node_types;

nlohmann::json topology_json(const TopoGraph& g);

}  // namespace fleetmap::web
