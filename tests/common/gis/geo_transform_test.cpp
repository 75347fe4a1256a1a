#include "common/gis/geo_transform.h"

#include <geodesic.h>
#include <gtest/gtest.h>

#include <cmath>

#include "common/core/error.h"

namespace fleetmap {
namespace {

// PROJ's own geodesic (Karney's algorithm): the point at distance d and azimuth az
// (degrees clockwise from north) from (lat0, lon0) on WGS 84.
LonLat geodesic_direct(double lat0, double lon0, double az, double d) {
  geod_geodesic g;
  geod_init(&g, 6378137, 1 / 298.257223563);
  double lat = 0, lon = 0;
  geod_direct(&g, lat0, lon0, az, d, &lat, &lon, nullptr);
  return {lon, lat};
}

TEST(GeoTransform, OriginMapsToZero) {
  const GeoTransform t(georef_from_origin(49.26, -123.25, 0.3));
  const Point p = t.to_map({-123.25, 49.26});
  EXPECT_NEAR(p.x, 0, 1e-9);
  EXPECT_NEAR(p.y, 0, 1e-9);
}

TEST(GeoTransform, ThousandMetresNorthIsThousandMetresAlongY) {
  const GeoTransform t(georef_from_origin(49.26, -123.25, 0));
  const Point p = t.to_map(geodesic_direct(49.26, -123.25, 0, 1000));
  EXPECT_NEAR(p.x, 0, 1e-3);
  EXPECT_NEAR(p.y, 1000, 1e-3);
}

TEST(GeoTransform, HeadingRotatesTheMapFrame) {
  // Heading 90 degrees: the map x axis points north.
  const GeoTransform t(georef_from_origin(45.7, 3.1, M_PI / 2));
  const Point p = t.to_map(geodesic_direct(45.7, 3.1, 0, 500));
  EXPECT_NEAR(p.x, 500, 1e-3);
  EXPECT_NEAR(p.y, 0, 1e-3);
}

TEST(GeoTransform, RoundTripsThroughWgs84) {
  MapGeoref g;
  g.crs = "EPSG:26910";
  g.tx = 480000;
  g.ty = 5455000;
  g.rotation = 0.2;
  g.scale = 1;
  const GeoTransform t(g);
  const Point m{123.456, -78.9};
  const Point back = t.to_map(t.to_wgs84(m));
  EXPECT_NEAR(back.x, m.x, 1e-6);
  EXPECT_NEAR(back.y, m.y, 1e-6);
}

TEST(GeoTransform, RefusesAGeographicOrUnknownCrs) {
  MapGeoref g;
  g.crs = "EPSG:4326";
  EXPECT_THROW(GeoTransform{g}, BadInput);
  g.crs = "EPSG:999999";
  EXPECT_THROW(GeoTransform{g}, BadInput);
  g.crs = "EPSG:26910";
  g.scale = 0;
  EXPECT_THROW(GeoTransform{g}, BadInput);
}

}  // namespace
}  // namespace fleetmap
