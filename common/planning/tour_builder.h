#pragma once
// A topological map from a guided tour (seed 003 §III): the guide's events, in order,
// become the nodes of a TopoGraph, each placed on the stored segment map as Fig. 2 says
// (tour_placement.h), joined by edges typed as the guide announced (tour_event.h).
//
//   kind           node position                            edge it starts
//   EnterCorridor  centred between the corridor walls       corridor
//   EnterRoom      the pose (rooms have no structure to      room
//                  measure, seed 003 §IV)
//   Door           centred between the door posts           door
//   Crossing       centred in the crossing (most clearance)  (keeps the current type)
//   Place          the pose, with the place's name          (keeps the current type)
//
// The edge from the previous event's node to this one has the type announced last
// (first_edge before any announcement). A place passed again is the same node: an event
// whose node would lie within merge_distance of an existing node of the same kind
// re-uses it (the nearest), and a named place re-uses the place of that name wherever it
// is; an edge between two nodes already joined is not added again, nor one from a node
// to itself.
//
//   TourGraph t = build_tour_graph(map, events, {.merge_distance = 1.5});
//   store.import("gdc1", t.graph, "tour", /*replace=*/true);
#include <vector>

#include "common/map/map.h"
#include "common/planning/topo_graph.h"
#include "common/planning/tour_event.h"
#include "common/planning/tour_placement.h"
#include "common/raycast/ray_caster.h"

namespace fleetmap {

struct TourBuildOptions {
  double merge_distance = 1.5;  // metres; 0: never merge by distance
  EdgeType first_edge = EdgeType::Corridor;
  bool measure = true;          // false: every node at the robot's pose (the baseline of bench-tour)
  TourPlacementOptions placement;
};

struct TourGraph {
  TopoGraph graph;                      // node ids 0, 1, ... in the order first placed
  std::vector<TourEventKind> kinds;     // per node (graph.nodes() order): the kind that placed it
  std::vector<bool> measured;           // per node: placed on the map, not at the pose
  std::vector<int> event_nodes;         // per event: the id of its node
};

// Throws TopoGraphError for a non-finite pose.
TourGraph build_tour_graph(const RayCaster& caster, const std::vector<TourEvent>& events,
                           const TourBuildOptions& o = {});
// Casts on the map with a caster of its own (rmax = placement.max_width).
TourGraph build_tour_graph(const Map& map, const std::vector<TourEvent>& events, const TourBuildOptions& o = {});

}  // namespace fleetmap
