#pragma once
// WGS84 fixes to map coordinates for a georeferenced map: the map origin's latitude and
// longitude and the heading of the map x axis (radians, counter-clockwise from east).
// A local tangent plane (equirectangular) approximation: error below 1 cm per km from
// the origin, ample for a campus or a city quarter.
#include <cmath>

#include "common/geometry/geometry.h"

namespace fleetmap {

struct GeoReference {
  double lat0 = 0, lon0 = 0, heading = 0;
};

inline Point to_map(const GeoReference& g, double lat, double lon) {
  constexpr double kEarthRadius = 6371008.8;  // mean radius, metres
  constexpr double kDeg = M_PI / 180;
  const double east = (lon - g.lon0) * kDeg * kEarthRadius * std::cos(g.lat0 * kDeg);
  const double north = (lat - g.lat0) * kDeg * kEarthRadius;
  const double c = std::cos(g.heading), s = std::sin(g.heading);
  return {c * east + s * north, -s * east + c * north};
}

}  // namespace fleetmap
