#pragma once
// Planning through the topological graph (SPEC 7, seed 003 §II): the graph gives the
// route, RRT-Connect the metric legs between its places. For a start and a goal:
//
//   1. connect: each end to the few nearest graph nodes it sees (a clear straight
//      motion for the robot's disc); when it sees none, to the nearest clear node, the
//      leg then planned by RRT-Connect (step 3);
//   2. route: A* on the graph (TopoGraph::route) between every start and goal candidate,
//      with the robot's edge rules (stairs only for a robot that climbs them, edges whose
//      max_clearance admits its radius); the route minimising
//      |start - a| + route(a, b) + |b - goal| wins;
//   3. legs: start, the route's clear nodes, goal; each consecutive pair joined by a
//      straight motion when it is clear, else by RRT-Connect (+ greedy shortcut);
//   4. the legs concatenated and smoothed again (PathSmoother), which keeps every
//      segment clear.
//
// The answer carries the route (node ids and edge indices) as well as the path: the
// robot switches behaviour per edge (seed 003 §II-B: corridor following, door passing).
// When start and goal see each other the path is the straight line and the route is
// empty. Same thread safety as MapPlanner: plan() is const and may run concurrently.
//
//   TopoPlanner tp(planner, graph);
//   TopoPlanResult r = tp.plan({1, 2}, {140, 18});
//   if (r.path) use(*r.path, r.route.nodes, r.route.edges);
#include <cstddef>
#include <optional>
#include <vector>

#include "common/planning/map_planner.h"
#include "common/planning/topo_graph.h"

namespace fleetmap {

struct TopoPlanOptions {
  size_t candidates = 4;  // nearest nodes tried at each end (step 1)
};

struct TopoPlanResult {
  PlanStatus status = PlanStatus::NoPath;
  std::optional<Path> path;  // smoothed, when found
  double length = 0;         // of *path, metres
  TopoRoute route;           // nodes and edges followed; empty for the straight line
  size_t rrt_legs = 0;       // legs that needed RRT-Connect (not a straight motion)
  std::optional<Collision> collision;  // why start or goal is blocked
  double seconds = 0;
};

class TopoPlanner {
 public:
  // Both must outlive the TopoPlanner. The planner gives the clearance checker, the
  // robot (stairs), the RRT and smoothing options; its rrt.max_time bounds all the legs.
  TopoPlanner(const MapPlanner& planner, const TopoGraph& graph, const TopoPlanOptions& options = {});

  TopoPlanResult plan(Point start, Point goal) const;

  RouteOptions route_options() const;

 private:
  struct Candidate {
    int node;
    double cost;  // straight-line metres to the end
  };
  std::vector<Candidate> candidates(Point p) const;

  const MapPlanner& planner_;
  const TopoGraph& graph_;
  TopoPlanOptions opt_;
};

}  // namespace fleetmap
