#pragma once
// A map's georeference from control points: places whose position is known both in the
// map frame and on the ground (surveyed corners, a CAD plan's ground control points, GPS
// fixes where the robot was localized). Seed 001 appendix on GIS: an existing map, not
// built by the robot, placed on Earth.
//
// The fit is a least-squares similarity (Umeyama 1991, with scale) from the map frame
// to the local Transverse Mercator at the points' mean fix (local_tm_crs): a conformal
// metric plane whose scale error stays below 1.2e-6 within 10 km, so distances there are
// ground metres. Its result is a MapGeoref like any other: SendGPS and the exports use it
// through GeoTransform.
#include <vector>

#include "common/geometry/geometry.h"
#include "common/gis/geo_transform.h"
#include "common/map/map_georef.h"

namespace fleetmap {

struct ControlPoint {
  Point map;   // metres, the map frame
  LonLat fix;  // degrees, WGS 84
};

struct ControlPointFit {
  MapGeoref georef;               // crs = local_tm_crs(mean fix); tx, ty, rotation, scale
  std::vector<double> residuals;  // metres on the ground, per point: |fitted(map) - fix|
  double rms = 0;                 // root mean square of the residuals, metres
  // The similarity's scale, base metres per map metre (= georef.scale). A map in metres
  // fits with scale close to 1; far from it, the map's units or the points are wrong
  // (kScaleTolerance).
  double scale = 1;
};

// The CLI refuses a fit whose scale is further than this from 1 unless told otherwise:
// 1 % is 1 m per 100 m, more than any survey or CAD plan in metres is off, and far less
// than a unit mistake (cm: 0.01, feet: 0.3048).
inline constexpr double kScaleTolerance = 0.01;

// Throws BadInput naming the point ("control point 2: lat: expected ...") on a
// non-finite or out-of-range coordinate, on fewer than 2 points, or when the points do
// not span a direction (all at one place on the map or on the ground).
ControlPointFit fit_control_points(const std::vector<ControlPoint>& points);

}  // namespace fleetmap
