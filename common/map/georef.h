#pragma once
// WGS84 fixes to map coordinates for a georeferenced map: the map origin's latitude and
// longitude and the heading of the map x axis (radians, counter-clockwise from east).
// A local tangent plane (equirectangular) approximation: error below 1 cm per km from
// the origin, ample for a campus or a city quarter.
//
// fit_georeference finds that reference from control points, places whose position is
// known both ways (surveyed corners, GPS fixes where the robot was localized).
#include <cmath>
#include <vector>

#include "common/geometry/geometry.h"

namespace fleetmap {

struct GeoReference {
  double lat0 = 0, lon0 = 0, heading = 0;
};

inline constexpr double kEarthRadiusM = 6371008.8;  // mean radius, metres
inline constexpr double kRadPerDeg = M_PI / 180;

inline Point to_map(const GeoReference& g, double lat, double lon) {
  const double east = (lon - g.lon0) * kRadPerDeg * kEarthRadiusM * std::cos(g.lat0 * kRadPerDeg);
  const double north = (lat - g.lat0) * kRadPerDeg * kEarthRadiusM;
  const double c = std::cos(g.heading), s = std::sin(g.heading);
  return {c * east + s * north, -s * east + c * north};
}

struct ControlPoint {
  double lat = 0, lon = 0;  // degrees, WGS84
  Point map;                // metres, the map frame
};

struct GeoReferenceFit {
  GeoReference georef;
  // Root mean square of |to_map(georef, lat, lon) - map| over the points, metres.
  double rms_m = 0;
  // Scale of the best similarity (Helmert) transform. The map is in metres, so the
  // reference itself has none; far from 1 it says the points or the map's units are wrong.
  double scale = 1;
};

// Least squares over >= 2 control points: the rotation and origin minimising the squared
// distances (Umeyama 1991, without scale: the model to_map applies), and the similarity
// fit's scale. Throws std::invalid_argument naming the point on a non-finite or
// out-of-range coordinate, on fewer than two points, or when the points do not span a
// direction (all at one place on the map or on the ground).
GeoReferenceFit fit_georeference(const std::vector<ControlPoint>& points);

}  // namespace fleetmap
