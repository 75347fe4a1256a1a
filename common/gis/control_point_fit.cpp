#include "common/gis/control_point_fit.h"

#include <cmath>
#include <cstdio>
#include <string>

#include "common/core/error.h"

// g++ 12 at -O3 sees Eigen::umeyama's 2-vector copies as 16-byte reads of 8-byte
// objects (-Wstringop-overread, a false positive of its SSE2 path); -Werror would fail.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wstringop-overread"
#endif
#include <Eigen/Geometry>

namespace fleetmap {

namespace {

// Points closer together than this on the map (or on the ground) give no direction.
constexpr double kMinSpreadM = 1e-3;

std::string number(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.10g", v);
  return b;
}

void check(const std::vector<ControlPoint>& points) {
  if (points.size() < 2)
    throw BadInput("control points: expected at least 2, got " + std::to_string(points.size()));
  for (size_t i = 0; i < points.size(); ++i) {
    const ControlPoint& p = points[i];
    const std::string at = "control point " + std::to_string(i + 1) + ": ";
    if (!std::isfinite(p.fix.lat) || p.fix.lat < -90 || p.fix.lat > 90)
      throw BadInput(at + "lat: expected degrees in [-90, 90], got " + number(p.fix.lat));
    if (!std::isfinite(p.fix.lon) || p.fix.lon < -180 || p.fix.lon > 180)
      throw BadInput(at + "lon: expected degrees in [-180, 180], got " + number(p.fix.lon));
    if (!std::isfinite(p.map.x) || !std::isfinite(p.map.y))
      throw BadInput(at + "x, y: expected finite map coordinates, got " + number(p.map.x) + ", " + number(p.map.y));
  }
}

// Largest distance of a column from the columns' mean.
double spread(const Eigen::Matrix2Xd& m) {
  return (m.colwise() - m.rowwise().mean()).colwise().norm().maxCoeff();
}

// The points' mean fix; longitudes are unwrapped around the first one so that points on
// both sides of the antimeridian average to a place between them, not across the globe.
LonLat mean_fix(const std::vector<ControlPoint>& points) {
  const double lon_ref = points.front().fix.lon;
  LonLat m{0, 0};
  for (const ControlPoint& p : points) {
    double d = p.fix.lon - lon_ref;
    if (d > 180) d -= 360;
    if (d < -180) d += 360;
    m.lon += (lon_ref + d) / static_cast<double>(points.size());
    m.lat += p.fix.lat / static_cast<double>(points.size());
  }
  if (m.lon > 180) m.lon -= 360;
  if (m.lon < -180) m.lon += 360;
  return m;
}

}  // namespace

ControlPointFit fit_control_points(const std::vector<ControlPoint>& points) {
  check(points);
  const size_t n = points.size();
  Eigen::Matrix2Xd xy(2, n);
  for (size_t i = 0; i < n; ++i) xy.col(static_cast<Eigen::Index>(i)) << points[i].map.x, points[i].map.y;
  if (spread(xy) < kMinSpreadM)
    throw BadInput("control points: expected at least two distinct map positions, got all at one place");

  // The fixes in the local TM at their mean: east, north in ground metres.
  const LonLat centre = mean_fix(points);
  const GeoTransform plane(georef_from_origin(centre.lat, centre.lon, 0));
  Eigen::Matrix2Xd en(2, n);
  for (size_t i = 0; i < n; ++i) {
    const Point p = plane.to_map(points[i].fix);
    en.col(static_cast<Eigen::Index>(i)) << p.x, p.y;
  }
  if (spread(en) < kMinSpreadM)
    throw BadInput("control points: expected at least two distinct fixes, got all at one place");

  // en = c R xy + t: exactly MapGeoref's base = (tx, ty) + scale R(rotation) map.
  const Eigen::Matrix3d t = Eigen::umeyama(xy, en, true);
  const Eigen::Matrix2d cr = t.topLeftCorner<2, 2>();
  ControlPointFit fit;
  fit.georef.crs = local_tm_crs(centre.lat, centre.lon);
  fit.georef.tx = t(0, 2);
  fit.georef.ty = t(1, 2);
  fit.georef.rotation = std::atan2(cr(1, 0), cr(0, 0));
  fit.georef.scale = std::sqrt(cr.determinant());
  fit.scale = fit.georef.scale;

  const GeoTransform fitted(fit.georef);
  double sq = 0;
  for (size_t i = 0; i < n; ++i) {
    const Point b = fitted.map_to_base(points[i].map);
    const double r = std::hypot(b.x - en(0, static_cast<Eigen::Index>(i)), b.y - en(1, static_cast<Eigen::Index>(i)));
    fit.residuals.push_back(r);
    sq += r * r;
  }
  fit.rms = std::sqrt(sq / static_cast<double>(n));
  return fit;
}

}  // namespace fleetmap

#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif
