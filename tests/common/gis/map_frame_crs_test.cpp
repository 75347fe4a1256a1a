#include "common/gis/map_frame_crs.h"

#include <ogr_spatialref.h>
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "common/core/error.h"
#include "common/geometry/geometry.h"

namespace fleetmap {
namespace {

std::unique_ptr<OGRSpatialReference> read(const std::string& wkt) {
  auto s = std::make_unique<OGRSpatialReference>();
  s->SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  EXPECT_EQ(s->importFromWkt(wkt.c_str()), OGRERR_NONE) << wkt;
  return s;
}

// (x, y) in `from` to `to` as OGR computes it (GIS axis order).
Point transform(const OGRSpatialReference& from, const OGRSpatialReference& to, Point p) {
  std::unique_ptr<OGRCoordinateTransformation> t(OGRCreateCoordinateTransformation(&from, &to));
  EXPECT_TRUE(t);
  if (!t) return {NAN, NAN};
  EXPECT_TRUE(t->Transform(1, &p.x, &p.y));
  return p;
}

TEST(MapFrameCrs, UnreferencedFrameIsAnEngineeringCrsInMetres) {
  const auto s = read(map_frame_crs_wkt("room \"A\"", std::nullopt));
  EXPECT_TRUE(s->IsLocal());
  EXPECT_DOUBLE_EQ(s->GetLinearUnits(), 1.0);
  EXPECT_NE(std::string(s->GetName()).find("room \"A\""), std::string::npos);
}

TEST(MapFrameCrs, FrameThatIsItsCrsKeepsTheEpsgCode) {
  const auto s = read(map_frame_crs_wkt("ubc", MapGeoref{"EPSG:26910", 0, 0, 0, 1}));
  EXPECT_STREQ(s->GetAuthorityName(nullptr), "EPSG");
  EXPECT_STREQ(s->GetAuthorityCode(nullptr), "26910");
}

// The derived CRS against the similarity written out by hand, then the base CRS as
// OGR reads it from its EPSG code: base = t + k R(θ) map.
TEST(MapFrameCrs, RotatedScaledFrameIsDerivedFromItsBase) {
  const MapGeoref g{"EPSG:26910", 483250.5, 5456120.25, 0.7, 1.0004};
  const auto derived = read(map_frame_crs_wkt("floor", g));
  EXPECT_FALSE(derived->IsLocal());
  OGRSpatialReference base;
  base.importFromEPSG(26910);
  base.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  for (const Point m : {Point{0, 0}, Point{10, 0}, Point{0, 10}, Point{-350.25, 1200.5}}) {
    const double c = std::cos(g.rotation), s = std::sin(g.rotation);
    const Point want{g.tx + g.scale * (c * m.x - s * m.y), g.ty + g.scale * (s * m.x + c * m.y)};
    const Point got = transform(*derived, base, m);
    EXPECT_NEAR(got.x, want.x, 1e-6) << m.x << "," << m.y;
    EXPECT_NEAR(got.y, want.y, 1e-6) << m.x << "," << m.y;
    const Point back = transform(base, *derived, want);
    EXPECT_NEAR(back.x, m.x, 1e-6);
    EXPECT_NEAR(back.y, m.y, 1e-6);
  }
}

// Read back (a map taken out through the GIS layers and imported again): the base CRS
// and the similarity given above, to rounding; the base compared by OGR.
TEST(MapFrameCrs, DerivedFrameReadsBackAsItsBaseAndSimilarity) {
  const MapGeoref g{"EPSG:26910", 483250.5, 5456120.25, 2.3, 1.0004};
  const std::optional<MapGeoref> back = georef_from_frame_crs(map_frame_crs_wkt("floor", g));
  ASSERT_TRUE(back);
  EXPECT_NEAR(back->tx, g.tx, 1e-6);
  EXPECT_NEAR(back->ty, g.ty, 1e-6);
  EXPECT_NEAR(back->rotation, g.rotation, 1e-12);
  EXPECT_NEAR(back->scale, g.scale, 1e-12);
  OGRSpatialReference utm;
  utm.importFromEPSG(26910);
  EXPECT_TRUE(read(back->crs)->IsSame(&utm)) << back->crs;
}

TEST(MapFrameCrs, OnlyADerivedSimilarityReadsBack) {
  EXPECT_FALSE(georef_from_frame_crs(map_frame_crs_wkt("room", std::nullopt)));
  EXPECT_FALSE(georef_from_frame_crs(map_frame_crs_wkt("ubc", MapGeoref{"EPSG:26910", 0, 0, 0, 1})));
  EXPECT_FALSE(georef_from_frame_crs("not a crs"));
  // A shear is an affine but no similarity: the map frame would not be metric.
  std::string wkt = map_frame_crs_wkt("floor", MapGeoref{"EPSG:26910", 10, 20, 0, 1});
  const size_t b2 = wkt.find("PARAMETER[\"B2\",");
  ASSERT_NE(b2, std::string::npos);
  wkt.replace(b2, wkt.find(',', b2 + 15) - b2, "PARAMETER[\"B2\",1.5");
  read(wkt);  // still a CRS OGR reads
  EXPECT_FALSE(georef_from_frame_crs(wkt));
}

TEST(MapFrameCrs, UnusableBaseIsBadInput) {
  EXPECT_THROW(map_frame_crs_wkt("x", MapGeoref{"EPSG:4326", 1, 2, 0.1, 1}), BadInput);
  EXPECT_THROW(map_frame_crs_wkt("x", MapGeoref{"not a crs", 0, 0, 0, 1}), BadInput);
}

}  // namespace
}  // namespace fleetmap
