#pragma once
// The WGS 84 longitude/latitude OutputFrame of a georeferenced map, through PROJ
// (GeoTransform): what RFC 7946 GeoJSON holds (section 4), 9 decimals of a degree
// (0.1 mm or less on the ground).
#include "common/io/output_frame.h"
#include "common/map/map_georef.h"

namespace fleetmap {

// Throws BadInput when PROJ cannot use the georeference.
OutputFrame wgs84_frame(const MapGeoref& georef);

}  // namespace fleetmap
