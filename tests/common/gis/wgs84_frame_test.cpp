// GeoJSON in WGS 84 (common/io writers through common/gis/wgs84_frame): read back by
// OGR's GeoJSON driver, the coordinates agree with PROJ called directly on the local
// Transverse Mercator written out here, within 1 mm, up to 10 km from the origin.
#include "common/gis/wgs84_frame.h"

#include <gtest/gtest.h>

#include <cstdio>

#include <nlohmann/json.hpp>

#include "common/gis/geo_transform.h"
#include "common/io/map_geojson.h"
#include "common/io/scene_geojson.h"
#include "common/io/topo_geojson.h"
#include "tests/common/gis/ogr_test_util.h"

namespace fleetmap {
namespace {

constexpr double kLat = 49.2606, kLon = -123.2460, kHeading = 0.35;

// The expected lon/lat of a map point: the rotation by hand, then PROJ on the TM at
// the origin (its definition written here, not taken from local_tm_crs).
Point expected(Point m) {
  static const test::ProjToWgs84 proj("+proj=tmerc +lat_0=49.2606 +lon_0=-123.246 +k=1 +x_0=0 +y_0=0 +ellps=WGS84 "
                                      "+units=m +no_defs +type=crs");
  const double c = std::cos(kHeading), s = std::sin(kHeading);
  return proj({c * m.x - s * m.y, s * m.x + c * m.y});
}

Map far_map() {
  Map m;
  m.border = {-10000, 10000, 10000, -10000};
  Obstacle o;
  o.id = 1;
  o.type = ShapeType::OpenPolygon;
  for (Point a : {Point{0.5, 0.25}, Point{1000, 0}, Point{0, -1000}, Point{7071, 7071}, Point{-10000, 3}}) {
    Segment s;
    s.a = a;
    s.b = {a.x + 1, a.y + 1};
    s.h = 2;
    o.segments.push_back(s);
  }
  m.obstacles.push_back(o);
  return m;
}

TEST(Wgs84Frame, MapGeoJsonAgreesWithProjWithinAMillimetre) {
  const Map m = far_map();
  const std::string path = test::scratch("far.geojson");
  {
    std::FILE* f = std::fopen(path.c_str(), "w");
    const std::string text = write_geojson(m, "far", wgs84_frame(georef_from_origin(kLat, kLon, kHeading)));
    std::fputs(text.c_str(), f);
    std::fclose(f);
  }
  test::Dataset ds = test::open_vector(path);
  ASSERT_TRUE(ds);
  OGRLayer* l = ds->GetLayer(0);
  OGRSpatialReference wgs84;
  wgs84.SetWellKnownGeogCS("WGS84");
  wgs84.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  ASSERT_NE(l->GetSpatialRef(), nullptr);
  EXPECT_TRUE(l->GetSpatialRef()->IsSame(&wgs84));
  size_t segments = 0;
  for (auto& f : *l) {
    if (std::string(f->GetFieldAsString("kind")) != "segment") continue;
    const Segment& s = m.obstacles[0].segments[segments++];
    const OGRLineString* line = f->GetGeometryRef()->toLineString();
    EXPECT_LT(test::ground_metres({line->getX(0), line->getY(0)}, expected(s.a)), 1e-3) << s.a.x << "," << s.a.y;
    EXPECT_LT(test::ground_metres({line->getX(1), line->getY(1)}, expected(s.b)), 1e-3);
  }
  EXPECT_EQ(segments, m.obstacles[0].segments.size());
}

TEST(Wgs84Frame, SceneAndTopologyToo) {
  const OutputFrame f = wgs84_frame(georef_from_origin(kLat, kLon, kHeading));
  Scene s;
  s.avoided.push_back({"a1", {{0, 0}, {10, 0}, {10, 10}}});
  const nlohmann::json scene = nlohmann::json::parse(write_scene_geojson(s, f));
  EXPECT_EQ(scene.at("fleetmap").at("frame"), "wgs84");
  const auto& c = scene.at("features")[0].at("geometry").at("coordinates")[0][1];
  EXPECT_LT(test::ground_metres({c[0], c[1]}, expected({10, 0})), 1e-3);
  // An export in WGS 84 is refused by the reader, which takes map-frame metres.
  EXPECT_THROW(read_scene_geojson(scene.dump()), SceneFormatError);
  TopoGraph g;
  g.add_node({7, {100, 200}, "dock"});
  const nlohmann::json topo = nlohmann::json::parse(write_topo_geojson(g, "lab", f));
  const auto& p = topo.at("features")[0].at("geometry").at("coordinates");
  EXPECT_LT(test::ground_metres({p[0], p[1]}, expected({100, 200})), 1e-3);
  EXPECT_EQ(topo.at("features")[0].at("id"), 1);
}

}  // namespace
}  // namespace fleetmap
