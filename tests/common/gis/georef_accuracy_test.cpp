// The georeference's accuracy (common/gis/geo_transform.h) measured against PROJ's own
// geodesic (Karney's algorithm, <geodesic.h>), an independent computation on the WGS 84
// ellipsoid: a map georeferenced by origin and heading must put the point at geodesic
// distance d and azimuth az from the origin at d along az in the map frame, within 1 mm
// at 1 km and 1 cm at 10 km (docs/georeference.md). The old equirectangular formula on a
// sphere is printed beside it for comparison, not asserted.
#include <geodesic.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "common/gis/geo_transform.h"

namespace fleetmap {
namespace {

constexpr double kDeg = M_PI / 180;

struct Geodesic {
  geod_geodesic g;
  Geodesic() { geod_init(&g, 6378137, 1 / 298.257223563); }
  LonLat direct(LonLat from, double az_deg, double d) const {
    double lat = 0, lon = 0;
    geod_direct(&g, from.lat, from.lon, az_deg, d, &lat, &lon, nullptr);
    return {lon, lat};
  }
  double distance(LonLat a, LonLat b) const {
    double s = 0;
    geod_inverse(&g, a.lat, a.lon, b.lat, b.lon, &s, nullptr, nullptr);
    return s;
  }
};

// Where a point at distance d, azimuth az (clockwise from north) lies in a map whose x
// axis points heading (counter-clockwise from east): east, north rotated by -heading.
Point expected_map(double az_deg, double d, double heading) {
  const double e = d * std::sin(az_deg * kDeg), n = d * std::cos(az_deg * kDeg);
  const double c = std::cos(heading), s = std::sin(heading);
  return {c * e + s * n, -s * e + c * n};
}

// The replaced formula (equirectangular on the mean sphere), kept here only to measure it.
Point equirectangular_map(LonLat origin, double heading, LonLat ll) {
  constexpr double kEarthRadiusM = 6371008.8;
  const double east = (ll.lon - origin.lon) * kDeg * kEarthRadiusM * std::cos(origin.lat * kDeg);
  const double north = (ll.lat - origin.lat) * kDeg * kEarthRadiusM;
  const double c = std::cos(heading), s = std::sin(heading);
  return {c * east + s * north, -s * east + c * north};
}

struct Worst {
  double to_map = 0, to_wgs84 = 0, old = 0;
};

// 16 azimuths at distance d from origin under the origin + heading georeference.
Worst measure(LonLat origin, double heading, double d) {
  const Geodesic geod;
  const GeoTransform t(georef_from_origin(origin.lat, origin.lon, heading));
  Worst w;
  for (int k = 0; k < 16; ++k) {
    const double az = k * 22.5;
    const LonLat truth = geod.direct(origin, az, d);
    const Point want = expected_map(az, d, heading);
    const Point got = t.to_map(truth);
    w.to_map = std::max(w.to_map, std::hypot(got.x - want.x, got.y - want.y));
    w.to_wgs84 = std::max(w.to_wgs84, geod.distance(t.to_wgs84(want), truth));
    const Point old = equirectangular_map(origin, heading, truth);
    w.old = std::max(w.old, std::hypot(old.x - want.x, old.y - want.y));
  }
  return w;
}

struct Case {
  double lat, lon, heading;
};

class GeorefAccuracy : public ::testing::TestWithParam<Case> {};

TEST_P(GeorefAccuracy, MatchesTheGeodesicWithinAMillimetrePerKmAndACentimetreAtTenKm) {
  const Case c = GetParam();
  const LonLat origin{c.lon, c.lat};
  const Worst km1 = measure(origin, c.heading, 1000);
  const Worst km10 = measure(origin, c.heading, 10000);
  std::printf("lat %6.2f heading %5.2f: PROJ worst %.2e m at 1 km, %.2e m at 10 km; "
              "equirectangular worst %.3f m at 1 km, %.2f m at 10 km\n",
              c.lat, c.heading, km1.to_map, km10.to_map, km1.old, km10.old);
  EXPECT_LE(km1.to_map, 1e-3);
  EXPECT_LE(km1.to_wgs84, 1e-3);
  EXPECT_LE(km10.to_map, 1e-2);
  EXPECT_LE(km10.to_wgs84, 1e-2);
}

INSTANTIATE_TEST_SUITE_P(LatitudesAndHeadings, GeorefAccuracy,
                         ::testing::Values(Case{0, 3.1, 0}, Case{0, -60, 2.0}, Case{30.2862, -97.7366, 0.4},
                                           Case{45, 3.1, 0}, Case{45, 3.1, -2.5}, Case{-45, 151.2, 1.2},
                                           Case{70, 25, 0}, Case{70, 25, 0.7}, Case{-70, -60, -1.0}));

// The figure: 1 000 m due north of a campus at 30.29 N came out 1 003.05 m with
// the sphere; through PROJ it is 1 000 m.
TEST(GeorefAccuracy, ThousandMetresNorth) {
  const Geodesic geod;
  const LonLat origin{-97.7366, 30.2862};
  const LonLat north = geod.direct(origin, 0, 1000);
  const Point proj = GeoTransform(georef_from_origin(origin.lat, origin.lon, 0)).to_map(north);
  const Point old = equirectangular_map(origin, 0, north);
  std::printf("1000 m north of (30.2862 N, 97.7366 W): PROJ %.6f m, equirectangular %.3f m\n", proj.y, old.y);
  EXPECT_NEAR(proj.y, 1000, 1e-6);
  EXPECT_NEAR(proj.x, 0, 1e-6);
}

}  // namespace
}  // namespace fleetmap
