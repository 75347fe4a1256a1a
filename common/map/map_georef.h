#pragma once
// A map's georeference: where the map frame sits on Earth (seed 001 appendix on GIS).
// The map frame is placed in a projected, metric CRS, the base, by a similarity:
//
//   base = (tx, ty) + scale * R(rotation) * map
//
// The base CRS is any definition PROJ reads: "EPSG:26910" (a map imported from UTM data
// keeps its source's frame: identity), a WKT, or a PROJ string such as the local
// Transverse Mercator of a map georeferenced by an origin and a heading
// (common/gis/geo_transform.h). Plain data: the database stores it, common/gis computes
// with it.
#include <string>

namespace fleetmap {

struct MapGeoref {
  std::string crs;         // the base CRS, as PROJ reads it
  double tx = 0, ty = 0;   // base coordinates of the map origin
  double rotation = 0;     // radians, counter-clockwise: the map x axis in the base CRS
  double scale = 1;        // base units per map metre (1 for a metric map)
  // The map frame is the base CRS itself, so GIS tools can be given that CRS as is.
  bool frame_is_crs() const { return tx == 0 && ty == 0 && rotation == 0 && scale == 1; }
  friend bool operator==(const MapGeoref&, const MapGeoref&) = default;
};

}  // namespace fleetmap
