#include "common/io/trajectory_geojson.h"

#include <cmath>
#include <stdexcept>

#include <nlohmann/json.hpp>

namespace fleetmap {
namespace {

using Json = nlohmann::ordered_json;  // "type" first

std::string dump(const Json& j, const std::string& where) {
  try {
    return j.dump();
  } catch (const nlohmann::json::type_error& e) {
    throw std::invalid_argument("trajectory GeoJSON: expected UTF-8 text in " + where + ", got: " + e.what());
  }
}

}  // namespace

std::string write_trajectory_geojson(const std::vector<Track>& tracks, const std::string& map_name,
                                     const OutputFrame& frame) {
  const Json header = {{"map", map_name}, {"frame", frame.name}, {"units", frame.units}, {"layer", "trajectories"}};
  std::string out = "{\"type\":\"FeatureCollection\",\"fleetmap\":" + dump(header, "the map name") + ",\"features\":[";
  const char* sep = "\n";
  size_t id = 0;
  for (const Track& track : tracks) {
    for (const TrackPose& p : track.poses) {
      const std::string where = "robot " + track.robot + " pose at " + p.t;
      for (double v : {p.pos.x, p.pos.y, p.theta, p.v})
        if (!std::isfinite(v)) throw std::invalid_argument("trajectory GeoJSON: expected finite numbers in " + where);
      const Point q = frame.apply(p.pos);
      const Json f = {{"type", "Feature"},
                      {"id", ++id},
                      {"geometry", {{"type", "Point"}, {"coordinates", {q.x, q.y}}}},
                      {"properties", {{"robot", track.robot}, {"t", p.t}, {"theta", p.theta}, {"v", p.v}}}};
      out += sep + dump(f, where);
      sep = ",\n";
    }
  }
  return out + "\n]}\n";
}

}  // namespace fleetmap
