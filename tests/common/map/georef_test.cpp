// Georeferencing (common/map/georef.h): to_map against figures worked by hand, then the
// control-point fit on points made from a known reference by the inverse written out here.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>

#include "common/map/georef.h"

namespace fleetmap {
namespace {

constexpr double kMetresPerDeg = 6371008.8 * M_PI / 180;  // 111 195.08 m

// The inverse of the tangent-plane model, by hand: (east, north) = R(heading) (x, y).
ControlPoint from_map(const GeoReference& g, double x, double y) {
  const double c = std::cos(g.heading), s = std::sin(g.heading);
  const double east = c * x - s * y, north = s * x + c * y;
  return {g.lat0 + north / kMetresPerDeg, g.lon0 + east / (kMetresPerDeg * std::cos(g.lat0 * M_PI / 180)), {x, y}};
}

// How far apart two references put the map origin, metres.
double origin_offset(const GeoReference& a, const GeoReference& b) {
  const Point p = to_map(a, b.lat0, b.lon0);
  return std::hypot(p.x, p.y);
}

const GeoReference kCampus{30.2862, -97.7366, 0.4};  // near UT Austin, x axis 23 deg north of east

std::vector<ControlPoint> campus_points() {
  return {from_map(kCampus, 12, 7), from_map(kCampus, 310, -45), from_map(kCampus, 150, 420),
          from_map(kCampus, -80, 260), from_map(kCampus, 500, 300)};
}

TEST(ToMap, OriginIsZero) {
  const Point p = to_map(kCampus, kCampus.lat0, kCampus.lon0);
  EXPECT_NEAR(p.x, 0, 1e-9);
  EXPECT_NEAR(p.y, 0, 1e-9);
}

TEST(ToMap, NorthAndEastAtHeadingZero) {
  // 0.001 deg of latitude: 111.19508 m north; of longitude at 60 deg: half of it east.
  const GeoReference g{60, 10, 0};
  const Point n = to_map(g, 60.001, 10);
  EXPECT_NEAR(n.x, 0, 1e-9);
  EXPECT_NEAR(n.y, 111.19508, 1e-4);
  const Point e = to_map(g, 60, 10.001);
  EXPECT_NEAR(e.x, 55.59754, 1e-4);
  EXPECT_NEAR(e.y, 0, 1e-9);
}

TEST(ToMap, HeadingTurnsTheAxes) {
  // x axis pointing north (heading +90 deg): north is +x, east is -y.
  const GeoReference g{0, 0, M_PI / 2};
  const Point n = to_map(g, 0.001, 0);
  EXPECT_NEAR(n.x, 111.19508, 1e-4);
  EXPECT_NEAR(n.y, 0, 1e-9);
  const Point e = to_map(g, 0, 0.001);
  EXPECT_NEAR(e.x, 0, 1e-9);
  EXPECT_NEAR(e.y, -111.19508, 1e-4);
}

TEST(FitGeoreference, RecoversAKnownReferenceFromExactPoints) {
  const GeoReferenceFit f = fit_georeference(campus_points());
  EXPECT_NEAR(f.georef.heading, kCampus.heading, 1e-9);
  EXPECT_LT(origin_offset(f.georef, kCampus), 1e-4);
  EXPECT_LT(f.rms_m, 1e-4);
  EXPECT_NEAR(f.scale, 1, 1e-6);
}

TEST(FitGeoreference, TwoPointsAreEnough) {
  const GeoReference g{-33.9, 151.2, -2.5};  // southern hemisphere, east of Greenwich
  const GeoReferenceFit f = fit_georeference({from_map(g, 0, 0), from_map(g, 100, 50)});
  EXPECT_NEAR(f.georef.heading, g.heading, 1e-9);
  EXPECT_LT(origin_offset(f.georef, g), 1e-4);
}

TEST(FitGeoreference, OriginFarFromThePoints) {
  // Control points 2 km from the map origin: the plane's cos(lat0) must be the origin's.
  const GeoReference g{52.0, 4.3, 1.0};
  const GeoReferenceFit f =
      fit_georeference({from_map(g, 2000, 2000), from_map(g, 2100, 2000), from_map(g, 2000, 2150)});
  EXPECT_LT(origin_offset(f.georef, g), 1e-3);
  EXPECT_LT(f.rms_m, 1e-3);
}

TEST(FitGeoreference, NoisyPointsGiveASmallResidual) {
  std::mt19937_64 rng(7);
  std::normal_distribution<double> noise(0, 0.05);  // 5 cm on the map
  std::vector<ControlPoint> pts;
  for (int i = 0; i < 40; ++i) {
    ControlPoint p = from_map(kCampus, 12.5 * i, 300 - 7.0 * i + (i % 5) * 40);
    p.map = {p.map.x + noise(rng), p.map.y + noise(rng)};
    pts.push_back(p);
  }
  const GeoReferenceFit f = fit_georeference(pts);
  EXPECT_GT(f.rms_m, 0.02);  // the noise is there, not fitted away
  EXPECT_LT(f.rms_m, 0.1);
  EXPECT_NEAR(f.georef.heading, kCampus.heading, 1e-3);
  EXPECT_LT(origin_offset(f.georef, kCampus), 0.1);
}

TEST(FitGeoreference, ReportsTheScaleOfAMapInOtherUnits) {
  std::vector<ControlPoint> pts = campus_points();
  for (ControlPoint& p : pts) p.map = {p.map.x / 0.3048, p.map.y / 0.3048};  // feet
  const GeoReferenceFit f = fit_georeference(pts);
  // 1e-4 relative: the rigid fit's origin, misplaced by the wrong units, moves cos(lat0).
  EXPECT_NEAR(f.scale, 1 / 0.3048, 3e-4);
  EXPECT_GT(f.rms_m, 50);  // a metre reference cannot fit a map in feet
}

TEST(FitGeoreference, RefusesTooFewPoints) {
  EXPECT_THROW(fit_georeference({}), std::invalid_argument);
  EXPECT_THROW(fit_georeference({from_map(kCampus, 1, 2)}), std::invalid_argument);
}

TEST(FitGeoreference, RefusesDegenerateSets) {
  ControlPoint a = from_map(kCampus, 10, 10), b = from_map(kCampus, 50, 10);
  ControlPoint same_place = b;
  same_place.map = a.map;  // two fixes, one map position
  EXPECT_THROW(fit_georeference({a, same_place}), std::invalid_argument);
  ControlPoint same_fix = a;
  same_fix.map = b.map;  // two map positions, one fix
  EXPECT_THROW(fit_georeference({a, same_fix}), std::invalid_argument);
}

TEST(FitGeoreference, RefusesBadCoordinatesNamingThePoint) {
  ControlPoint bad = from_map(kCampus, 10, 10);
  bad.lat = 91;
  try {
    fit_georeference({from_map(kCampus, 0, 0), bad});
    FAIL() << "expected invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("control point 2: lat"), std::string::npos) << e.what();
  }
  ControlPoint nan = from_map(kCampus, 10, 10);
  nan.map.x = std::nan("");
  EXPECT_THROW(fit_georeference({from_map(kCampus, 0, 0), nan}), std::invalid_argument);
}

}  // namespace
}  // namespace fleetmap
