#pragma once
// A guide's tour through a known topological graph, for simulations and benchmarks of
// tour acquisition (seed 003 §III, docs/topology-tour.md): a waypoint list that walks
// every edge of the component of `start` depth first (out along an edge, back along it
// when its far end has nothing new), with the event the guide would announce at each
// node it reaches, told from the graph alone:
//
//   degree >= 3 -> crossing;  degree 1 -> place (its name, or "node <id>");  otherwise -> corridor
//
// Every edge is announced as a corridor: door and room edges would need the guide to say
// "door" in front of the door and "room" behind it, which the graph's nodes do not mark
// (the AMRL graphs have no rooms, GDC1's none of either).
// Nodes reached again announce again: the builder is expected to merge them.
#include <optional>
#include <string>
#include <vector>

#include "common/planning/topo_graph.h"
#include "common/planning/tour_event.h"

namespace fleetmap {

struct TourWaypoint {
  Point p;
  std::optional<TourEventKind> event;  // nullopt: only a point to walk through
  std::string name;                    // for a place
  int node = -1;                       // the graph node it stands on, -1: none
  friend bool operator==(const TourWaypoint&, const TourWaypoint&) = default;
};

// Throws TopoNodeNotFound for an unknown start.
std::vector<TourWaypoint> tour_of_graph(const TopoGraph& g, int start);

// The same tour walked `offset` metres to the right of the way (a guide keeping right,
// not on the graph's lines): each waypoint moved right of the direction it is reached
// from (the first: of the one it is left in).
std::vector<TourWaypoint> keep_right(std::vector<TourWaypoint> tour, double offset);

}  // namespace fleetmap
