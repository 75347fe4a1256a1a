// GeoJSON view of a topological graph (common/io/topo_geojson.h).
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "common/io/topo_geojson.h"
#include "common/io/topo_json.h"

namespace fleetmap {
namespace {

TEST(TopoGeoJson, OnePointPerNodeAndOneLinePerEdge) {
  const TopoGraph g = read_topo_json(R"({
    "nodes": [{"id": 4, "loc": {"x": 0, "y": 0}, "name": "dock"}, {"id": 2, "loc": {"x": 3, "y": 4}}],
    "edges": [{"s0_id": 4, "s1_id": 2, "has_stairs": true, "max_clearance": 1.5},
              {"s0_id": 2, "s1_id": 4, "type": "room"}]})");
  const std::string text = write_topo_geojson(g, "lab");
  // The header line, one line per feature (2 nodes, 2 edges), the closing line.
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 1 + 4 + 1);
  const auto j = nlohmann::json::parse(text);
  EXPECT_EQ(j["type"], "FeatureCollection");
  EXPECT_EQ(j["fleetmap"]["map"], "lab");
  EXPECT_EQ(j["fleetmap"]["units"], "m");
  const auto& f = j["features"];
  ASSERT_EQ(f.size(), 4u);
  EXPECT_EQ(f[0]["geometry"]["type"], "Point");
  EXPECT_EQ(f[0]["properties"]["id"], 4);
  EXPECT_EQ(f[0]["properties"]["name"], "dock");
  EXPECT_FALSE(f[1]["properties"].contains("name"));
  EXPECT_EQ(f[1]["geometry"]["coordinates"], nlohmann::json({3.0, 4.0}));
  EXPECT_EQ(f[2]["geometry"]["type"], "LineString");
  EXPECT_EQ(f[2]["geometry"]["coordinates"], nlohmann::json({{0.0, 0.0}, {3.0, 4.0}}));
  EXPECT_EQ(f[2]["properties"]["type"], "stairs");
  EXPECT_EQ(f[2]["properties"]["length"], 5.0);
  EXPECT_EQ(f[2]["properties"]["max_clearance"], 1.5);
  EXPECT_FALSE(f[2]["properties"].contains("max_speed"));  // no limit: absent
  EXPECT_EQ(f[3]["properties"]["edge"], 1);
  EXPECT_EQ(f[3]["properties"]["type"], "room");
  EXPECT_EQ(f[3]["geometry"]["coordinates"], nlohmann::json({{3.0, 4.0}, {0.0, 0.0}}));
}

}  // namespace
}  // namespace fleetmap
