#pragma once
// The frame a GeoJSON document of a stored map is written in, for every front door (the
// export commands' --crs, the web API's ?crs=).
//
// GeoJSON is WGS 84 longitude/latitude (RFC 7946 section 4), so a georeferenced map is
// written in WGS 84 by default; map-frame metres only when asked for ("map": the prior
// arrangement of section 4, said by the "fleetmap" member; the browser console reads
// it). A map without a georeference has no WGS 84.
#include <optional>
#include <string>

#include "common/io/output_frame.h"
#include "common/map/map_georef.h"

namespace fleetmap {

// crs: "" (WGS 84, which needs a georeference), "map", "wgs84" or "base". Throws BadInput
// when the map `name` has no georeference and crs is not "map", and for "base" (GeoJSON
// has no CRS member); BadInput from PROJ when it cannot use the georeference.
OutputFrame geojson_frame(const std::string& crs, const std::string& name, const std::optional<MapGeoref>& georef);

}  // namespace fleetmap
