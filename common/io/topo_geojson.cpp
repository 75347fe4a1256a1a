#include "common/io/topo_geojson.h"

#include <cmath>
#include <stdexcept>

#include <nlohmann/json.hpp>

namespace fleetmap {
namespace {

// Keeps "type" first, as GeoJSON readers and people expect.
using Json = nlohmann::ordered_json;

std::string dump(const Json& j) {
  try {
    return j.dump();
  } catch (const nlohmann::json::type_error& e) {
    throw std::invalid_argument(std::string("GeoJSON: expected UTF-8 text, got: ") + e.what());
  }
}

Json node_feature(const TopoNode& n) {
  Json props = {{"kind", "node"}, {"id", n.id}};
  if (!n.name.empty()) props["name"] = n.name;
  return {{"type", "Feature"},
          {"geometry", {{"type", "Point"}, {"coordinates", {n.pos.x, n.pos.y}}}},
          {"properties", std::move(props)}};
}

Json edge_feature(const TopoGraph& g, size_t k) {
  const TopoEdge& e = g.edges()[k];
  const Point a = g.node(e.a).pos, b = g.node(e.b).pos;
  Json props = {{"kind", "edge"},
                {"edge", k},
                {"s0_id", e.a},
                {"s1_id", e.b},
                {"type", std::string(to_string(e.type))},
                {"has_door", e.door},
                {"has_automated_door", e.automated_door},
                {"length", g.length(k)}};
  if (std::isfinite(e.max_clearance)) props["max_clearance"] = e.max_clearance;
  if (std::isfinite(e.max_speed)) props["max_speed"] = e.max_speed;
  return {{"type", "Feature"},
          {"geometry", {{"type", "LineString"}, {"coordinates", {{a.x, a.y}, {b.x, b.y}}}}},
          {"properties", std::move(props)}};
}

}  // namespace

std::string write_topo_geojson(const TopoGraph& g, const std::string& name) {
  const Json header = {{"map", name}, {"frame", "map"}, {"units", "m"}, {"layer", "topology"}};
  std::string out = "{\"type\":\"FeatureCollection\",\"fleetmap\":" + dump(header) + ",\"features\":[";
  const char* sep = "\n";
  for (const TopoNode& n : g.nodes()) {
    out += sep + dump(node_feature(n));
    sep = ",\n";
  }
  for (size_t k = 0; k < g.edges().size(); ++k) {
    out += sep + dump(edge_feature(g, k));
    sep = ",\n";
  }
  out += "\n]}\n";
  return out;
}

}  // namespace fleetmap
