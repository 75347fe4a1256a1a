// The navigation-graph JSON reader and writer (common/io/topo_json.h): malformed input is
// refused with the element's index and field; real files round-trip byte for byte.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "common/io/topo_json.h"

namespace fleetmap {
namespace {

const std::string kMaps = FLEETMAP_REAL_MAPS;

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// Two valid nodes around whatever edges / extra nodes a case needs.
std::string doc(const std::string& edges, const std::string& more_nodes = "") {
  return R"({"nodes": [{"id": 0, "loc": {"x": 0, "y": 0}}, {"id": 1, "loc": {"x": 3, "y": 4}})" + more_nodes +
         R"(], "edges": [)" + edges + "]}";
}
const std::string kEdge = R"({"s0_id": 0, "s1_id": 1, "max_clearance": 1.0, "max_speed": 2.0})";

struct Bad {
  std::string text;
  std::string where;    // TopoFormatError::where()
  std::string message;  // a part of TopoFormatError::message()
};

TEST(TopoJson, MalformedInputNamesTheElementAndField) {
  const Bad cases[] = {
      {"[1, 2]", "(top level)", "expected an object with \"nodes\" and \"edges\", got an array"},
      {R"({"edges": []})", "nodes", "expected an array, the member is missing"},
      {R"({"nodes": {}, "edges": []})", "nodes", "expected an array, got an object"},
      {R"({"nodes": []})", "edges", "expected an array, the member is missing"},
      {doc("", R"(, 5)"), "nodes[2]", "expected an object with \"id\" and \"loc\", got 5"},
      {doc("", R"(, {"loc": {"x": 1, "y": 1}})"), "nodes[2].id", "expected a value, the member is missing"},
      {doc("", R"(, {"id": "7", "loc": {"x": 1, "y": 1}})"), "nodes[2].id", "expected an integer id, got \"7\""},
      {doc("", R"(, {"id": 2.5, "loc": {"x": 1, "y": 1}})"), "nodes[2].id", "expected an integer id, got 2.5"},
      {doc("", R"(, {"id": -3, "loc": {"x": 1, "y": 1}})"), "nodes[2].id", "expected an id in 0..2147483647, got -3"},
      {doc("", R"(, {"id": 4294967296, "loc": {"x": 1, "y": 1}})"), "nodes[2].id", "expected an id in 0..2147483647"},
      {doc("", R"(, {"id": 1, "loc": {"x": 1, "y": 1}})"), "nodes[2].id",
       "expected a unique id, got 1 as in nodes[1]"},
      {doc("", R"(, {"id": 2})"), "nodes[2].loc", "expected a value, the member is missing"},
      {doc("", R"(, {"id": 2, "loc": [1, 2]})"), "nodes[2].loc", "expected an object with \"x\" and \"y\""},
      {doc("", R"(, {"id": 2, "loc": {"x": 1}})"), "nodes[2].loc.y", "expected a value, the member is missing"},
      {doc("", R"(, {"id": 2, "loc": {"x": null, "y": 1}})"), "nodes[2].loc.x", "expected a number, got null"},
      {doc("", R"(, {"id": 2, "loc": {"x": 1, "y": 1e999}})"), "nodes[2].loc.y",
       "expected a finite number, got 1e999, too large for a double"},
      {doc("", R"(, {"id": 2, "loc": {"x": 1, "y": 1}, "name": 3})"), "nodes[2].name", "expected a string, got 3"},
      {doc(kEdge + R"(, "corridor")"), "edges[1]", "expected an object with \"s0_id\" and \"s1_id\""},
      {doc(kEdge + R"(, {"s1_id": 0})"), "edges[1].s0_id", "expected a value, the member is missing"},
      {doc(kEdge + R"(, {"s0_id": 0, "s1_id": 7})"), "edges[1].s1_id", "expected the id of a node, got 7"},
      {doc(R"({"s0_id": 9, "s1_id": 0})"), "edges[0].s0_id", "expected the id of a node, got 9"},
      {doc(R"({"s0_id": 1, "s1_id": 1})"), "edges[0].s1_id", "expected a node other than s0_id, got 1 twice"},
      {doc(R"({"s0_id": 0, "s1_id": 1, "has_stairs": "yes"})"), "edges[0].has_stairs",
       "expected true or false, got \"yes\""},
      {doc(R"({"s0_id": 0, "s1_id": 1, "has_door": 1})"), "edges[0].has_door", "expected true or false, got 1"},
      {doc(R"({"s0_id": 0, "s1_id": 1, "has_stairs": true, "has_elevator": true})"), "edges[0].has_elevator",
       "expected stairs or an elevator, got both"},
      {doc(R"({"s0_id": 0, "s1_id": 1, "max_clearance": -0.5})"), "edges[0].max_clearance",
       "expected a clearance >= 0, got -0.5"},
      {doc(R"({"s0_id": 0, "s1_id": 1, "max_clearance": "wide"})"), "edges[0].max_clearance",
       "expected a number, got \"wide\""},
      {doc(R"({"s0_id": 0, "s1_id": 1, "max_speed": 0})"), "edges[0].max_speed", "expected a speed > 0, got 0"},
      {doc(R"({"s0_id": 0, "s1_id": 1, "max_speed": -1e999})"), "edges[0].max_speed",
       "expected a finite number, got -1e999, too large for a double"},
      {R"({"nodes": [{"id": 0, "loc": {"x": 0, "y": 0}}, [1e400]]})", "nodes[1][0]", "expected a finite number"},
      {doc(R"({"s0_id": 0, "s1_id": 1, "type": "hall"})"), "edges[0].type",
       "expected one of corridor, room, door, stairs, elevator, got \"hall\""},
      {doc(R"({"s0_id": 0, "s1_id": 1, "type": 2})"), "edges[0].type", "expected one of corridor"},
      {doc(R"({"s0_id": 0, "s1_id": 1, "has_stairs": true, "type": "room"})"), "edges[0].type",
       "expected \"stairs\" as the has_* flags say, got \"room\""},
      {doc(R"({"s0_id": 0, "s1_id": 1, "has_automated_door": true, "type": "corridor"})"), "edges[0].type",
       "expected \"door\" as the has_* flags say, got \"corridor\""},
  };
  for (const Bad& c : cases) {
    SCOPED_TRACE(c.text);
    try {
      (void)read_topo_json(c.text, "bad.json");
      ADD_FAILURE() << "accepted";
    } catch (const TopoFormatError& e) {
      EXPECT_EQ(e.file(), "bad.json");
      EXPECT_EQ(e.where(), c.where) << e.what();
      EXPECT_NE(e.message().find(c.message), std::string::npos) << e.what();
      EXPECT_EQ(std::string(e.what()), "bad.json: " + e.where() + ": " + e.message());
    }
  }
}

TEST(TopoJson, SyntaxErrorsNameLineAndColumn) {
  try {
    (void)read_topo_json("{\n  \"nodes\": [\n    {\"id\": 0,, }\n  ]\n}\n", "broken.json");
    FAIL() << "accepted";
  } catch (const TopoFormatError& e) {
    EXPECT_EQ(e.where(), "line 3, column 14") << e.what();  // the second comma
    EXPECT_NE(e.message().find("syntax error"), std::string::npos) << e.what();
  }
  try {
    (void)read_topo_json("", "empty.json");
    FAIL() << "accepted";
  } catch (const TopoFormatError& e) {
    EXPECT_EQ(e.where(), "line 1, column 1") << e.what();
  }
  try {
    (void)read_topo_json_file("/nonexistent/graph.json");
    FAIL() << "accepted";
  } catch (const IoError& e) {  // not malformed: an I/O failure (README "Exit codes")
    EXPECT_EQ(std::string(e.what()).rfind("/nonexistent/graph.json: ", 0), 0u) << e.what();
  }
}

TEST(TopoJson, OptionalMembersHaveDefaultsAndUnknownOnesAreIgnored) {
  const TopoGraph g = read_topo_json(
      doc(R"({"s0_id": 0, "s1_id": 1, "comment": "new AMRL field"},
             {"s0_id": 1, "s1_id": 0, "type": "room", "max_clearance": 0.5},
             {"s0_id": 0, "s1_id": 1, "has_automated_door": true},
             {"s0_id": 0, "s1_id": 1, "has_door": true, "has_stairs": true, "type": "stairs"})",
          R"(, {"id": 9, "loc": {"x": -1.5, "y": 2, "z": 4}, "name": "charging station"})"));
  ASSERT_EQ(g.edges().size(), 4u);
  EXPECT_EQ(g.edges()[0].type, EdgeType::Corridor);
  EXPECT_EQ(g.edges()[0].max_clearance, std::numeric_limits<double>::infinity());
  EXPECT_EQ(g.edges()[0].max_speed, std::numeric_limits<double>::infinity());
  EXPECT_EQ(g.edges()[1].type, EdgeType::Room);
  EXPECT_EQ(g.edges()[1].max_clearance, 0.5);
  EXPECT_EQ(g.edges()[2].type, EdgeType::Door);
  EXPECT_TRUE(g.edges()[2].automated_door);
  EXPECT_EQ(g.edges()[3].type, EdgeType::Stairs);
  EXPECT_TRUE(g.edges()[3].door);
  EXPECT_EQ(g.node(9).name, "charging station");
  EXPECT_EQ(g.node(9).pos, (Point{-1.5, 2}));
  EXPECT_DOUBLE_EQ(g.length(0), 5);
}

TEST(TopoJson, RealFilesRoundTripByteForByte) {
  for (const char* file : {"GDC1.navigation.json", "UT_Campus.navigation.json"}) {
    SCOPED_TRACE(file);
    const std::string text = slurp(kMaps + "/" + file);
    const TopoGraph g = read_topo_json(text, file);
    EXPECT_EQ(write_topo_json(g), text);
  }
}

TEST(TopoJson, EveryTypeNameAndLimitRoundTrips) {
  TopoGraph g;
  g.add_node({3, {0.1, -2.5}, "dock"});
  g.add_node({1, {1e-7, 123456.789}, ""});
  g.add_node({2, {-0.0, 5}, "desk \"A\" / ä"});
  auto add = [&](int a, int b, EdgeType t, bool door, bool automated, double clearance, double speed) {
    TopoEdge e;
    e.a = a, e.b = b, e.type = t, e.door = door, e.automated_door = automated;
    e.max_clearance = clearance, e.max_speed = speed;
    g.add_edge(e);
  };
  const double inf = std::numeric_limits<double>::infinity();
  add(3, 1, EdgeType::Corridor, false, false, 1, 2);
  add(1, 2, EdgeType::Room, false, false, inf, 0.5);
  add(2, 3, EdgeType::Door, false, false, 0.45, inf);   // a door edge without the AMRL flag
  add(2, 3, EdgeType::Door, true, false, 0.45, 1);
  add(1, 3, EdgeType::Door, false, true, 0.45, 1);
  add(1, 3, EdgeType::Stairs, true, false, 1, 0.3);
  add(1, 2, EdgeType::Elevator, false, true, 1, 0.3);
  const std::string text = write_topo_json(g);
  EXPECT_EQ(read_topo_json(text), g) << text;
  // "type" is written only where the flags do not say it.
  EXPECT_NE(text.find("\"type\": \"room\""), std::string::npos);
  EXPECT_EQ(text.find("\"type\": \"stairs\""), std::string::npos);
  EXPECT_EQ(text.find("\"type\": \"corridor\""), std::string::npos);
}

}  // namespace
}  // namespace fleetmap
