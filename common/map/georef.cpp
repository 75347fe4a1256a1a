#include "common/map/georef.h"

#include <stdexcept>
#include <string>

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

void check(const std::vector<ControlPoint>& points) {
  if (points.size() < 2)
    throw std::invalid_argument("fit_georeference: expected at least 2 control points, got " +
                                std::to_string(points.size()));
  for (size_t i = 0; i < points.size(); ++i) {
    const ControlPoint& p = points[i];
    const std::string at = "fit_georeference: control point " + std::to_string(i + 1) + ": ";
    if (!std::isfinite(p.lat) || p.lat < -90 || p.lat > 90)
      throw std::invalid_argument(at + "lat: expected degrees in [-90, 90], got " + std::to_string(p.lat));
    if (!std::isfinite(p.lon) || p.lon < -180 || p.lon > 180)
      throw std::invalid_argument(at + "lon: expected degrees in [-180, 180], got " + std::to_string(p.lon));
    if (!std::isfinite(p.map.x) || !std::isfinite(p.map.y))
      throw std::invalid_argument(at + "x, y: expected finite map coordinates");
  }
}

// Largest distance of a column from the columns' mean.
double spread(const Eigen::Matrix2Xd& m) {
  return (m.colwise() - m.rowwise().mean()).colwise().norm().maxCoeff();
}

// East and north (metres) of every point in the tangent plane at ref, as to_map does.
Eigen::Matrix2Xd local_plane(const std::vector<ControlPoint>& points, const GeoReference& ref) {
  Eigen::Matrix2Xd en(2, points.size());
  for (size_t i = 0; i < points.size(); ++i) {
    const Point p = to_map({ref.lat0, ref.lon0, 0}, points[i].lat, points[i].lon);
    en.col(i) << p.x, p.y;
  }
  return en;
}

}  // namespace

GeoReferenceFit fit_georeference(const std::vector<ControlPoint>& points) {
  check(points);
  Eigen::Matrix2Xd xy(2, points.size());
  for (size_t i = 0; i < points.size(); ++i) xy.col(i) << points[i].map.x, points[i].map.y;
  if (spread(xy) < kMinSpreadM)
    throw std::invalid_argument("fit_georeference: control points: expected at least two distinct map positions");

  // The tangent plane first at the points' mean fix, then at the origin found: to_map
  // scales east by cos(lat0), so the fit matches it once the plane sits at lat0.
  GeoReference g;
  for (const ControlPoint& p : points) {
    g.lat0 += p.lat / points.size();
    g.lon0 += p.lon / points.size();
  }
  Eigen::Matrix2Xd en;
  for (int pass = 0; pass < 3; ++pass) {
    en = local_plane(points, g);
    if (spread(en) < kMinSpreadM)
      throw std::invalid_argument("fit_georeference: control points: expected at least two distinct fixes");
    // map = R en + t, R the rotation by -heading (to_map's).
    const Eigen::Matrix3d t = Eigen::umeyama(en, xy, false);
    const Eigen::Matrix2d r = t.topLeftCorner<2, 2>();
    const Eigen::Vector2d origin_en = -r.transpose() * t.topRightCorner<2, 1>();  // map (0, 0)
    const double lat_ref = g.lat0;
    g.lat0 += origin_en.y() / (kRadPerDeg * kEarthRadiusM);
    g.lon0 += origin_en.x() / (kRadPerDeg * kEarthRadiusM * std::cos(lat_ref * kRadPerDeg));
    g.heading = -std::atan2(r(1, 0), r(0, 0));
  }

  GeoReferenceFit fit;
  fit.georef = g;
  fit.scale = Eigen::umeyama(en, xy, true).topLeftCorner<2, 2>().determinant();
  fit.scale = std::sqrt(fit.scale);
  double sq = 0;
  for (const ControlPoint& p : points) {
    const Point m = to_map(g, p.lat, p.lon);
    sq += (m.x - p.map.x) * (m.x - p.map.x) + (m.y - p.map.y) * (m.y - p.map.y);
  }
  fit.rms_m = std::sqrt(sq / points.size());
  return fit;
}

}  // namespace fleetmap

#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif
