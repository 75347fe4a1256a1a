// GET /api/maps and GET /api/maps/{map}: the stored maps, and one map's walls as GeoJSON.
#include <nlohmann/json.hpp>

#include "common/io/map_geojson.h"
#include "protocol/map_store.h"
#include "server/web/api/map_frame.h"
#include "server/web/api/route_groups.h"

namespace fleetmap::web {
namespace {

nlohmann::json map_summary(const MapInfo& m) {
  const Rect r = m.border.rect();
  return {{"name", m.name},
          {"bounds", {r.xmin, r.ymin, r.xmax, r.ymax}},
          {"segments", m.segments},
          {"obstacles", m.obstacles},
          {"georeferenced", m.georef.has_value()},
          {"crs", m.georef ? nlohmann::json(m.georef->crs) : nlohmann::json()},
          {"revision", m.revision}};
}

ApiResponse list_maps(const ApiRequest&, ApiContext& ctx) {
  ApiResponse r;
  r.body = nlohmann::json::array();
  for (const MapInfo& m : MapStore(ctx.reader()).list()) r.body.push_back(map_summary(m));
  return r;
}

// The map's GeoJSON as `fleetmap map export --format geojson` writes it (common/io/
// map_geojson.h), each segment's properties led by the API's three: "obstacle" (its id),
// "type" (the shape type's name) and "h" (metres; 0 does not block).
std::string walls_geojson(const Map& m, const std::string& name, const OutputFrame& frame) {
  nlohmann::ordered_json doc = nlohmann::ordered_json::parse(write_geojson(m, name, frame));
  for (auto& f : doc["features"]) {
    nlohmann::ordered_json& p = f["properties"];
    if (p.value("kind", "") != "segment") continue;
    nlohmann::ordered_json lead = {{"obstacle", p["obstacle_id"]}, {"type", p["shape"]}, {"h", p["h"]}};
    for (auto it = p.begin(); it != p.end(); ++it)
      if (!lead.contains(it.key())) lead[it.key()] = it.value();
    p = std::move(lead);
  }
  return doc.dump();
}

ApiResponse map_walls(const ApiRequest& req, ApiContext& ctx) {
  const std::string& name = req.args.at(0);
  MapStore store(ctx.reader());
  MapInfo info;
  const Map m = store.load(name, &info);  // MapNotFound: 404
  return geojson_response(walls_geojson(m, name, requested_frame(req, name, info.georef)));
}

}  // namespace

std::vector<Route> maps_routes() {
  return {
      {"GET", "/api/maps", false, "the stored maps: name, bounds, counts, georeference, revision", list_maps},
      {"GET", "/api/maps/{map}", false, "a map's walls as GeoJSON (map frame; ?crs=wgs84 when georeferenced)",
       map_walls},
  };
}

}  // namespace fleetmap::web
