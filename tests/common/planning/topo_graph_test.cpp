// TopoGraph (common/planning/topo_graph.h): routes on hand-drawn graphs, stairs and clearance
// options, against Floyd–Warshall on random graphs and on the real AMRL graphs.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "common/planning/topo_graph.h"
#include "common/io/topo_json.h"

namespace fleetmap {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
const std::string kMaps = FLEETMAP_REAL_MAPS;

struct UnnamedNode {  // {id, {x, y}}: the hand graphs' nodes have no names
  int id;
  Point pos;
};

TopoGraph graph(const std::vector<UnnamedNode>& nodes, const std::vector<TopoEdge>& edges) {
  TopoGraph g;
  for (const UnnamedNode& n : nodes) g.add_node({n.id, n.pos, ""});
  for (const TopoEdge& e : edges) g.add_edge(e);
  return g;
}

TopoEdge edge(int a, int b, EdgeType t = EdgeType::Corridor, double clearance = kInf) {
  TopoEdge e;
  e.a = a;
  e.b = b;
  e.type = t;
  e.max_clearance = clearance;
  return e;
}

// All-pairs shortest lengths over the usable edges, written independently of TopoGraph.
std::vector<std::vector<double>> floyd_warshall(const TopoGraph& g, const RouteOptions& o) {
  const size_t n = g.nodes().size();
  std::vector<size_t> index_of_id;
  for (size_t i = 0; i < n; ++i) {
    const int id = g.nodes()[i].id;
    if (index_of_id.size() <= static_cast<size_t>(id)) index_of_id.resize(id + 1);
    index_of_id[id] = i;
  }
  std::vector<std::vector<double>> d(n, std::vector<double>(n, kInf));
  for (size_t i = 0; i < n; ++i) d[i][i] = 0;
  for (const TopoEdge& e : g.edges()) {
    if (o.avoid_stairs && e.type == EdgeType::Stairs) continue;
    if (!(e.max_clearance >= o.radius)) continue;
    const size_t a = index_of_id[e.a], b = index_of_id[e.b];
    const Point pa = g.nodes()[a].pos, pb = g.nodes()[b].pos;
    const double len = std::hypot(pa.x - pb.x, pa.y - pb.y);
    d[a][b] = std::min(d[a][b], len);
    d[b][a] = std::min(d[b][a], len);
  }
  for (size_t k = 0; k < n; ++k)
    for (size_t i = 0; i < n; ++i)
      for (size_t j = 0; j < n; ++j) d[i][j] = std::min(d[i][j], d[i][k] + d[k][j]);
  return d;
}

// A route is a walk along usable edges whose lengths add up to its length.
void expect_valid(const TopoGraph& g, const TopoRoute& r, int from, int to, const RouteOptions& o) {
  ASSERT_FALSE(r.nodes.empty());
  EXPECT_EQ(r.nodes.front(), from);
  EXPECT_EQ(r.nodes.back(), to);
  ASSERT_EQ(r.edges.size() + 1, r.nodes.size());
  double sum = 0;
  for (size_t i = 0; i < r.edges.size(); ++i) {
    const TopoEdge& e = g.edges().at(r.edges[i]);
    const bool joins = (e.a == r.nodes[i] && e.b == r.nodes[i + 1]) || (e.b == r.nodes[i] && e.a == r.nodes[i + 1]);
    EXPECT_TRUE(joins) << "edge " << r.edges[i] << " does not join " << r.nodes[i] << " and " << r.nodes[i + 1];
    EXPECT_TRUE(g.usable(r.edges[i], o));
    sum += g.length(r.edges[i]);
  }
  EXPECT_NEAR(sum, r.length, 1e-9 * (1 + sum));
}

TEST(TopoGraph, ShortestOfTwoWaysOnAHandGraph) {
  // Over the top: 5 + 5 = 10; under: 2 * sqrt(9 + 100) ~ 20.9.
  const TopoGraph g = graph({{0, {0, 0}}, {1, {3, 4}}, {2, {6, 0}}, {3, {3, -10}}},
                            {edge(0, 1), edge(1, 2), edge(0, 3), edge(3, 2)});
  auto r = g.route(0, 2);
  ASSERT_TRUE(r);
  EXPECT_EQ(r->nodes, (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(r->edges, (std::vector<size_t>{0, 1}));
  EXPECT_DOUBLE_EQ(r->length, 10);
  auto back = g.route(2, 0);
  ASSERT_TRUE(back);
  EXPECT_EQ(back->nodes, (std::vector<int>{2, 1, 0}));
  EXPECT_EQ(g.path(*back), (Path{{6, 0}, {3, 4}, {0, 0}}));
  // To 3: straight, not round.
  EXPECT_EQ(g.route(0, 3)->nodes, (std::vector<int>{0, 3}));
}

TEST(TopoGraph, SameNodeIsARouteOfOneNode) {
  const TopoGraph g = graph({{4, {1, 1}}, {7, {2, 2}}}, {edge(4, 7)});
  auto r = g.route(7, 7);
  ASSERT_TRUE(r);
  EXPECT_EQ(r->nodes, (std::vector<int>{7}));
  EXPECT_TRUE(r->edges.empty());
  EXPECT_EQ(r->length, 0);
}

TEST(TopoGraph, DisconnectedNodesHaveNoRouteAndUnknownIdsThrow) {
  const TopoGraph g = graph({{0, {0, 0}}, {1, {1, 0}}, {2, {5, 5}}}, {edge(0, 1)});
  EXPECT_FALSE(g.route(0, 2));
  EXPECT_EQ(g.components(), 2u);
  try {
    (void)g.route(0, 99);
    FAIL() << "expected TopoNodeNotFound";
  } catch (const TopoNodeNotFound& e) {
    EXPECT_EQ(e.id(), 99);
    EXPECT_STREQ(e.what(), "no node with id 99");
  }
  EXPECT_THROW((void)g.route(-1, 0), TopoNodeNotFound);
}

TEST(TopoGraph, AvoidingStairsTakesTheLongWayOrNone) {
  // 0 -> 1 is 10 m down the stairs, or 2 * sqrt(25 + 400) round by node 2.
  TopoGraph g = graph({{0, {0, 0}}, {1, {10, 0}}, {2, {5, 20}}},
                      {edge(0, 1, EdgeType::Stairs), edge(0, 2, EdgeType::Door), edge(2, 1, EdgeType::Room)});
  EXPECT_EQ(g.route(0, 1)->nodes, (std::vector<int>{0, 1}));
  auto wheeled = g.route(0, 1, {.avoid_stairs = true});
  ASSERT_TRUE(wheeled);
  EXPECT_EQ(wheeled->nodes, (std::vector<int>{0, 2, 1}));
  EXPECT_NEAR(wheeled->length, 2 * std::sqrt(425.0), 1e-12);

  // Without the detour, stairs are the only way: none for a wheeled robot.
  const TopoGraph only_stairs = graph({{0, {0, 0}}, {1, {10, 0}}}, {edge(0, 1, EdgeType::Stairs)});
  EXPECT_TRUE(only_stairs.route(0, 1));
  EXPECT_FALSE(only_stairs.route(0, 1, {.avoid_stairs = true}));
  // Elevators are not stairs.
  const TopoGraph lift = graph({{0, {0, 0}}, {1, {10, 0}}}, {edge(0, 1, EdgeType::Elevator)});
  EXPECT_TRUE(lift.route(0, 1, {.avoid_stairs = true}));
}

TEST(TopoGraph, ClearanceKeepsEdgesWideEnoughForTheRobot) {
  // Direct but narrow (0.3 m), or round by node 2 on 1 m wide edges.
  const TopoGraph g = graph({{0, {0, 0}}, {1, {10, 0}}, {2, {5, 5}}},
                            {edge(0, 1, EdgeType::Corridor, 0.3), edge(0, 2, EdgeType::Corridor, 1.0),
                             edge(2, 1, EdgeType::Corridor, 1.0)});
  EXPECT_EQ(g.route(0, 1, {.radius = 0.3})->nodes, (std::vector<int>{0, 1}));  // equal is enough
  EXPECT_EQ(g.route(0, 1, {.radius = 0.31})->nodes, (std::vector<int>{0, 2, 1}));
  EXPECT_EQ(g.route(0, 1, {.radius = 1.0})->nodes, (std::vector<int>{0, 2, 1}));
  EXPECT_FALSE(g.route(0, 1, {.radius = 1.01}));
  // No limit given: every robot fits.
  const TopoGraph open = graph({{0, {0, 0}}, {1, {10, 0}}}, {edge(0, 1)});
  EXPECT_TRUE(open.route(0, 1, {.radius = 1e6}));
}

TEST(TopoGraph, ParallelEdgesReportTheEdgeTaken) {
  const TopoGraph g = graph({{0, {0, 0}}, {1, {0, 3}}}, {edge(0, 1, EdgeType::Stairs), edge(1, 0, EdgeType::Elevator)});
  auto r = g.route(0, 1, {.avoid_stairs = true});
  ASSERT_TRUE(r);
  EXPECT_EQ(r->edges, (std::vector<size_t>{1}));
  EXPECT_EQ(g.edges()[r->edges[0]].type, EdgeType::Elevator);
}

TEST(TopoGraph, MatchesFloydWarshallOnRandomGraphs) {
  std::mt19937 rng(2024);
  std::uniform_real_distribution<double> coord(-100, 100), clearance(0.2, 2.0);
  const RouteOptions options[] = {{}, {.avoid_stairs = true}, {.radius = 0.8}, {.avoid_stairs = true, .radius = 1.2}};
  size_t routes = 0, none = 0;
  for (int trial = 0; trial < 40; ++trial) {
    const int n = 5 + static_cast<int>(rng() % 30);
    std::vector<UnnamedNode> nodes;
    std::vector<int> ids;
    for (int i = 0; i < n; ++i) ids.push_back(3 * i + 1);  // not 0..n-1: ids are not indices
    std::shuffle(ids.begin(), ids.end(), rng);
    for (int id : ids) nodes.push_back({id, {coord(rng), coord(rng)}});
    std::vector<TopoEdge> edges;
    const int m = static_cast<int>(rng() % (2 * n + 1));
    for (int k = 0; k < m; ++k) {
      const int a = ids[rng() % n], b = ids[rng() % n];
      if (a == b) continue;
      const EdgeType t = static_cast<EdgeType>(rng() % 5);
      edges.push_back(edge(a, b, t, clearance(rng)));
    }
    const TopoGraph g = graph(nodes, edges);
    for (const RouteOptions& o : options) {
      const auto d = floyd_warshall(g, o);
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
          const int from = g.nodes()[i].id, to = g.nodes()[j].id;
          const auto r = g.route(from, to, o);
          if (std::isinf(d[i][j])) {
            EXPECT_FALSE(r) << "trial " << trial << ": " << from << " -> " << to;
            ++none;
            continue;
          }
          ASSERT_TRUE(r) << "trial " << trial << ": " << from << " -> " << to;
          EXPECT_NEAR(r->length, d[i][j], 1e-9 * (1 + d[i][j]));
          expect_valid(g, *r, from, to, o);
          ++routes;
        }
    }
  }
  // Both outcomes were exercised.
  EXPECT_GT(routes, 1000u);
  EXPECT_GT(none, 1000u);
}

TEST(TopoGraph, NearestNode) {
  EXPECT_FALSE(TopoGraph{}.nearest_node({0, 0}));
  const TopoGraph g = graph({{5, {0, 0}}, {6, {10, 0}}, {7, {0, 10}}, {8, {10, 0}}}, {});
  EXPECT_EQ(g.nearest_node({1, 1}), 5);
  EXPECT_EQ(g.nearest_node({9, -3}), 6);  // 8 is as near; the first in node order wins
  EXPECT_EQ(g.nearest_node({-50, 40}), 7);
}

TEST(TopoGraph, BuildingRefusesBrokenGraphs) {
  TopoGraph g = graph({{0, {0, 0}}, {1, {1, 0}}}, {});
  EXPECT_THROW(g.add_node({1, {2, 2}, ""}), TopoGraphError);   // id taken
  EXPECT_THROW(g.add_node({-1, {2, 2}, ""}), TopoGraphError);  // negative id
  EXPECT_THROW(g.add_node({2, {NAN, 2}, ""}), TopoGraphError);
  EXPECT_THROW(g.add_node({2, {2, kInf}, ""}), TopoGraphError);
  EXPECT_THROW(g.add_edge(edge(0, 9)), TopoGraphError);
  EXPECT_THROW(g.add_edge(edge(1, 1)), TopoGraphError);
  EXPECT_THROW(g.add_edge(edge(0, 1, EdgeType::Corridor, -1)), TopoGraphError);
  EXPECT_THROW(g.add_edge(edge(0, 1, EdgeType::Corridor, NAN)), TopoGraphError);
  TopoEdge door_in_corridor = edge(0, 1);
  door_in_corridor.door = true;
  EXPECT_THROW(g.add_edge(door_in_corridor), TopoGraphError);
  door_in_corridor.type = EdgeType::Stairs;  // stairs behind a door: fine
  EXPECT_NO_THROW(g.add_edge(door_in_corridor));
  EXPECT_EQ(g.nodes().size(), 2u);
  EXPECT_EQ(g.edges().size(), 1u);
}

TEST(TopoGraph, EdgeTypeFromFlagsAndNames) {
  EXPECT_EQ(edge_type_from_flags(false, false, false, false), EdgeType::Corridor);
  EXPECT_EQ(edge_type_from_flags(true, false, false, false), EdgeType::Door);
  EXPECT_EQ(edge_type_from_flags(false, true, false, false), EdgeType::Door);
  EXPECT_EQ(edge_type_from_flags(false, false, true, false), EdgeType::Stairs);
  EXPECT_EQ(edge_type_from_flags(false, false, false, true), EdgeType::Elevator);
  EXPECT_EQ(edge_type_from_flags(true, true, true, false), EdgeType::Stairs);  // stairs first
  EXPECT_EQ(edge_type_from_flags(true, false, false, true), EdgeType::Elevator);
  for (EdgeType t : {EdgeType::Corridor, EdgeType::Room, EdgeType::Door, EdgeType::Stairs, EdgeType::Elevator})
    EXPECT_EQ(edge_type_from_string(to_string(t)), t);
  EXPECT_FALSE(edge_type_from_string("hall"));
  EXPECT_FALSE(edge_type_from_string("Corridor"));
}

// The real graphs: counts as an independent parse of the file says, and every pair's
// route as long as Floyd–Warshall's.
TEST(TopoGraph, RealGraphsRouteLikeFloydWarshall) {
  for (const char* file : {"GDC1.navigation.json", "UT_Campus.navigation.json"}) {
    SCOPED_TRACE(file);
    const std::string path = kMaps + "/" + file;
    std::ifstream in(path);
    const nlohmann::json j = nlohmann::json::parse(in);
    size_t stairs = 0;
    for (const auto& e : j["edges"]) stairs += e["has_stairs"].get<bool>();

    const TopoGraph g = read_topo_json_file(path);
    ASSERT_EQ(g.nodes().size(), j["nodes"].size());
    ASSERT_EQ(g.edges().size(), j["edges"].size());
    size_t typed_stairs = 0;
    for (const TopoEdge& e : g.edges()) typed_stairs += e.type == EdgeType::Stairs;
    EXPECT_EQ(typed_stairs, stairs);

    for (const RouteOptions& o : {RouteOptions{}, RouteOptions{.avoid_stairs = true, .radius = 1.0}}) {
      const auto d = floyd_warshall(g, o);
      for (size_t i = 0; i < g.nodes().size(); ++i)
        for (size_t k = 0; k < g.nodes().size(); ++k) {
          const int from = g.nodes()[i].id, to = g.nodes()[k].id;
          const auto r = g.route(from, to, o);
          ASSERT_EQ(r.has_value(), !std::isinf(d[i][k])) << from << " -> " << to;
          if (r) {
            EXPECT_NEAR(r->length, d[i][k], 1e-9 * (1 + d[i][k]));
            expect_valid(g, *r, from, to, o);
          }
        }
    }
  }
  // The campus graph is not connected (9 components: 91 nodes and 8 islands).
  EXPECT_EQ(read_topo_json_file(kMaps + "/UT_Campus.navigation.json").components(), 9u);
}

}  // namespace
}  // namespace fleetmap
