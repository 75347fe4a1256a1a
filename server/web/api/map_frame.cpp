#include "server/web/api/map_frame.h"

#include "server/core/geojson_frame.h"
#include "server/web/api/request_fields.h"

namespace fleetmap::web {

OutputFrame requested_frame(const ApiRequest& req, const std::string& map, const std::optional<MapGeoref>& georef) {
  const std::string crs = query_value(req, "crs").value_or("map");
  if (crs != "map" && crs != "wgs84") throw bad_field("crs", "expected map or wgs84, got '" + crs + "'");
  return geojson_frame(crs, map, georef);
}

ApiResponse geojson_response(std::string text) {
  ApiResponse r;
  r.raw = std::move(text);
  r.content_type = "application/geo+json";
  return r;
}

}  // namespace fleetmap::web
