#pragma once
// The frame exported coordinates are written in. RFC 7946 section 4: GeoJSON holds WGS 84
// longitude/latitude, another frame only "by prior arrangement"; fleetmap's arrangement
// is map-frame metres, said by the foreign member "fleetmap" (section 6.1), which the
// browser console reads (Leaflet CRS.Simple). The writers of common/io take the mapping
// as a function, so this layer stays free of PROJ: common/gis builds the WGS 84 one.
#include <functional>
#include <string>

#include "common/geometry/geometry.h"

namespace fleetmap {

struct OutputFrame {
  std::string name = "map";                // "map" or "wgs84": the "frame" of the "fleetmap" member
  std::string units = "m";                 // "m" or "degree"
  std::function<Point(Point)> from_map;    // map frame -> output (x = lon, y = lat); empty: identity
  // Decimals of the output coordinates; < 0: the shortest text that reads back to the
  // same double. 9 decimals of a degree are 0.1 mm or less on the ground.
  int decimals = -1;

  bool is_map() const { return !from_map; }
  // Throws std::invalid_argument when the mapping gives a number that is not finite.
  Point apply(Point map) const;
};

}  // namespace fleetmap
