// RouteEdges (client/route_edges.h): which edge of its route a robot is on, from a
// SetPath's nodes and edges; progress never goes back.
#include <gtest/gtest.h>

#include "client/route_edges.h"

namespace fleetmap {
namespace {

// An L: node 1 (0, 0) -> 2 (10, 0) corridor, 2 -> 3 (10, 10) door, 3 -> 4 (0, 10) room:
// the third edge runs back above the first.
SetPathParams l_route() {
  SetPathParams p;
  p.nodes = {{1, "a", 0, 0}, {2, "", 10, 0}, {3, "", 10, 10}, {4, "d", 0, 10}};
  p.edges = {{1, 2, "corridor"}, {2, 3, "door"}, {3, 4, "room"}};
  return p;
}

TEST(RouteEdges, ReportsEachEdgeOnceAsTheRobotEntersIt) {
  RouteEdges r(l_route());
  EXPECT_EQ(r.update({1, 0.2}), 0u);
  EXPECT_EQ(r.update({5, -0.3}), std::nullopt);  // still on the corridor
  EXPECT_EQ(r.update({9.8, 4}), 1u);
  EXPECT_EQ(r.edge(1).type, "door");
  EXPECT_EQ(r.update({6, 9.7}), 2u);
  EXPECT_EQ(r.edge(2).type, "room");
  // Back near the first edge's line (y = 0 is 6 m away, y = 10 is 4 m away): no going back.
  EXPECT_EQ(r.update({2, 4}), std::nullopt);
  EXPECT_EQ(r.current(), 2u);
}

TEST(RouteEdges, NoEdgesOrEdgesToUnknownNodes) {
  RouteEdges none(SetPathParams{{{0, 0}, {1, 1}}, 1.4, {}, {}});
  EXPECT_TRUE(none.empty());
  EXPECT_EQ(none.update({0, 0}), std::nullopt);
  SetPathParams p = l_route();
  p.edges.push_back({4, 99, "stairs"});  // node 99 is not in the answer
  RouteEdges r(p);
  EXPECT_EQ(r.update({0, 10}), 2u);  // the last known edge, not the malformed one
}

}  // namespace
}  // namespace fleetmap
