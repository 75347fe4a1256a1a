#pragma once
// The frame of a GeoJSON answer: ?crs=map (the default: map-frame metres, what the
// console draws with Leaflet's CRS.Simple) or ?crs=wgs84 (longitude/latitude, RFC 7946
// section 4, for a georeferenced map). One rule for every front door:
// server/core/geojson_frame.h, so a map without a georeference gets the message
// `fleetmap map export --format geojson` prints for it (400 bad_input).
#include <optional>
#include <string>

#include "common/io/output_frame.h"
#include "common/map/map_georef.h"
#include "server/web/api/api.h"

namespace fleetmap::web {

// Throws ApiError 400 for a crs other than map or wgs84, BadInput (400) for wgs84 on a
// map without a georeference.
OutputFrame requested_frame(const ApiRequest& req, const std::string& map, const std::optional<MapGeoref>& georef);

// 200, application/geo+json, the text as the writer made it.
ApiResponse geojson_response(std::string text);

}  // namespace fleetmap::web
