#include "server/core/geojson_frame.h"

#include "common/core/error.h"
#include "common/gis/wgs84_frame.h"

namespace fleetmap {

OutputFrame geojson_frame(const std::string& crs, const std::string& name, const std::optional<MapGeoref>& georef) {
  if (crs == "map") return {};
  if (crs == "base")
    throw BadInput("--crs base: GeoJSON holds WGS 84 (RFC 7946) or, by arrangement, the map frame; the base CRS "
                   "needs a format that says its CRS (--format gpkg or fgb)");
  if (!georef)
    throw BadInput("map '" + name + "' has no georeference, and GeoJSON is WGS 84 longitude/latitude (RFC 7946): "
                   "give --crs map for map-frame metres, --format gpkg for the map frame with its CRS, or "
                   "georeference the map (fleetmap map georef)");
  return wgs84_frame(*georef);
}

}  // namespace fleetmap
