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

Json xy(const OutputFrame& f, Point map) {
  const Point p = f.apply(map);
  return {p.x, p.y};
}

Json node_feature(const TopoNode& n, const OutputFrame& f, size_t id) {
  Json props = {{"kind", "node"}, {"id", n.id}};
  if (!n.name.empty()) props["name"] = n.name;
  return {{"type", "Feature"},
          {"id", id},
          {"geometry", {{"type", "Point"}, {"coordinates", xy(f, n.pos)}}},
          {"properties", std::move(props)}};
}

Json edge_feature(const TopoGraph& g, size_t k, const OutputFrame& f, size_t id) {
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
          {"id", id},
          {"geometry", {{"type", "LineString"}, {"coordinates", {xy(f, a), xy(f, b)}}}},
          {"properties", std::move(props)}};
}

}  // namespace

std::string write_topo_geojson(const TopoGraph& g, const std::string& name, const OutputFrame& frame) {
  const Json header = {{"map", name}, {"frame", frame.name}, {"units", frame.units}, {"layer", "topology"}};
  std::string out = "{\"type\":\"FeatureCollection\",\"fleetmap\":" + dump(header) + ",\"features\":[";
  const char* sep = "\n";
  size_t id = 0;
  for (const TopoNode& n : g.nodes()) {
    out += sep + dump(node_feature(n, frame, ++id));
    sep = ",\n";
  }
  for (size_t k = 0; k < g.edges().size(); ++k) {
    out += sep + dump(edge_feature(g, k, frame, ++id));
    sep = ",\n";
  }
  out += "\n]}\n";
  return out;
}

}  // namespace fleetmap
