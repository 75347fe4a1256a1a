#pragma once
// Which edge of its topological route the robot is on (seed 003 §II-B: the robot
// switches behaviour per edge, corridor following, door passing), from a SetPath that
// carries nodes and edges (docs/protocol.md, "SetPath: nodes and edges"), decoded by
// decode_set_path (protocol/params.h). The simulated robot only logs the change
// (client/sim/sim_robot.cpp); a real robot would switch its controller there.
//
// The edge is the one whose segment (between its end nodes' positions) is nearest to
// the robot, searched from the current edge onwards: progress along the route never
// goes back, so a robot passing near an earlier edge again (a route that doubles back)
// keeps the later one.
//
//   RouteEdges route(set_path);
//   if (auto e = route.update(pose.point())) spdlog::info("now on a {} edge", route.edge(*e).type);
#include <cstddef>
#include <optional>
#include <vector>

#include "common/geometry/geometry.h"
#include "protocol/params.h"

namespace fleetmap {

class RouteEdges {
 public:
  RouteEdges() = default;
  // Edges whose end nodes are not among p.nodes are skipped (a malformed route).
  explicit RouteEdges(const SetPathParams& p);

  bool empty() const { return edges_.empty(); }
  const PathEdge& edge(size_t i) const { return edges_.at(i).edge; }
  std::optional<size_t> current() const { return current_; }

  // The robot is at p: the index of the edge it has just entered, or nullopt when it is
  // still on the same one (or the route has no edges).
  std::optional<size_t> update(Point p);

 private:
  struct Located {
    PathEdge edge;
    Point a, b;
  };
  std::vector<Located> edges_;
  std::optional<size_t> current_;
};

}  // namespace fleetmap
