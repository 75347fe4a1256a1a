#include "common/io/map_geojson.h"

#include <cmath>
#include <stdexcept>

#include <nlohmann/json.hpp>

namespace fleetmap {
namespace {

// Keeps "type" first, as GeoJSON readers and people expect.
using Json = nlohmann::ordered_json;

void check_finite(std::initializer_list<double> values, const std::string& where) {
  for (double v : values)
    if (!std::isfinite(v))
      throw std::invalid_argument("GeoJSON: expected finite numbers in " + where + ", got a NaN or infinity");
}

// nlohmann's dump rejects invalid UTF-8 with its own type_error; report it in our terms.
std::string dump(const Json& j, const std::string& where) {
  try {
    return j.dump();
  } catch (const nlohmann::json::type_error& e) {
    throw std::invalid_argument("GeoJSON: expected UTF-8 text in " + where + ", got: " + e.what());
  }
}

Json xy(const OutputFrame& f, Point map) {
  const Point p = f.apply(map);
  return {p.x, p.y};
}

Json border_feature(const Border& b, const OutputFrame& f) {
  // Counter-clockwise with y upwards: lower-left, lower-right, upper-right, upper-left.
  // A similarity with scale > 0 and a conformal projection keep the orientation.
  Json ring = Json::array({xy(f, {b.mx1, b.my4}), xy(f, {b.mx4, b.my4}), xy(f, {b.mx4, b.my1}),
                           xy(f, {b.mx1, b.my1}), xy(f, {b.mx1, b.my4})});
  return {{"type", "Feature"},
          {"id", 0},
          {"geometry", {{"type", "Polygon"}, {"coordinates", Json::array({ring})}}},
          {"properties", {{"kind", "border"}}}};
}

Json segment_feature(const Obstacle& o, size_t index, const Segment& s, const OutputFrame& f, size_t id) {
  Json props = {{"kind", "segment"},
                {"obstacle_id", o.id},
                {"st", static_cast<int>(o.type)},
                {"shape", std::string(to_string(o.type))},
                {"obstacle_semantic", o.semantic},
                {"segment", index + 1},
                {"h", s.h},
                {"in_out", s.in_out},
                {"semantic", s.semantic}};
  if (!s.note.empty()) props["note"] = s.note;
  return {{"type", "Feature"},
          {"id", id},
          {"geometry", {{"type", "LineString"}, {"coordinates", {xy(f, s.a), xy(f, s.b)}}}},
          {"properties", std::move(props)}};
}

}  // namespace

std::string write_geojson(const Map& m, const std::string& name, const OutputFrame& frame) {
  const Border& b = m.border;
  check_finite({b.mx1, b.my1, b.mx4, b.my4}, "the border");
  Json header = {{"map", name}, {"frame", frame.name}, {"units", frame.units}};
  if (frame.is_map()) header["border"] = {b.mx1, b.my1, b.mx4, b.my4};

  std::string out = "{\"type\":\"FeatureCollection\",\"fleetmap\":" + dump(header, "the map name");
  out += ",\"features\":[\n";
  out += dump(border_feature(b, frame), "the border");
  size_t id = 0;
  for (const Obstacle& o : m.obstacles) {
    for (size_t i = 0; i < o.segments.size(); ++i) {
      const Segment& s = o.segments[i];
      const std::string where = "obstacle " + std::to_string(o.id) + " segment " + std::to_string(i + 1);
      check_finite({s.a.x, s.a.y, s.b.x, s.b.y, s.h}, where);
      out += ",\n";
      out += dump(segment_feature(o, i, s, frame, ++id), where);
    }
  }
  out += "\n]}\n";
  return out;
}

}  // namespace fleetmap
