#pragma once
// The CRS of a map frame as GIS tools read it (OGC WKT), for spatial_ref_sys and OGR
// writers (docs/gis-layers.md). Three cases, by the map's georeference
// (common/map/map_georef.h):
//   none             an engineering CRS: a local metric plane, x east, y north, that no
//                    tool will reproject onto the Earth (it is not on it);
//   frame is the CRS the base CRS itself (GeoTransform::base_wkt(), EPSG code kept);
//   rotated/offset   a derived projected CRS: the base CRS and, as its deriving
//                    conversion, the affine map = S^-1 (base - t) (EPSG method 9624),
//                    so PROJ and GDAL transform map coordinates onto the Earth exactly.
#include <optional>
#include <string>

#include "common/map/map_georef.h"

namespace fleetmap {

// Throws BadInput when the georeference's base CRS is unusable (as GeoTransform does).
std::string map_frame_crs_wkt(const std::string& map_name, const std::optional<MapGeoref>& georef);

// The reverse of the derived case: a DERIVEDPROJCRS (WKT2) in metres over a projected
// base whose deriving conversion is an affine (EPSG 9624) similarity gives the
// georeference {base CRS as WKT2, t, rotation, scale}; anything else gives nothing. So a
// map taken out through the GIS layers is imported back in its own frame.
std::optional<MapGeoref> georef_from_frame_crs(const std::string& wkt);

// The engineering CRS of an unreferenced map frame named after the map.
std::string engineering_crs_wkt(const std::string& map_name);

}  // namespace fleetmap
