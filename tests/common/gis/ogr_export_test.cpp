// common/gis/ogr_export: every export read back with OGR, checked against the map and
// scene it was made from, and coordinates against PROJ called directly.
#include "common/gis/ogr_export.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <set>

#include "common/core/error.h"
#include "common/io/scene_geojson.h"
#include "common/io/seed_format.h"
#include "tests/common/gis/ogr_test_util.h"

namespace fleetmap {
namespace {

using test::open_vector;
using test::scratch;
using test::source_file;

Map room() { return read_seed_file(source_file("maps/example-room.map")); }
Scene room_scene() { return read_scene_geojson(test::text_of(source_file("maps/example-room.geojson"))); }

std::map<std::string, OGRLayer*> layers_of(GDALDataset& ds) {
  std::map<std::string, OGRLayer*> out;
  for (OGRLayer* l : ds.GetLayers()) out[l->GetName()] = l;
  return out;
}

// One geometry type per layer, FIDs present and unique and equal to the "id" field,
// every polygon valid for GEOS.
void expect_clean_layer(OGRLayer& l) {
  SCOPED_TRACE(l.GetName());
  const OGRwkbGeometryType type = wkbFlatten(l.GetGeomType());
  EXPECT_NE(type, wkbUnknown);
  std::set<GIntBig> fids;
  l.ResetReading();
  for (auto& f : l) {
    EXPECT_NE(f->GetFID(), OGRNullFID);
    EXPECT_TRUE(fids.insert(f->GetFID()).second) << "FID " << f->GetFID() << " twice";
    EXPECT_EQ(f->GetFieldAsInteger64("id"), f->GetFID());
    const OGRGeometry* g = f->GetGeometryRef();
    ASSERT_NE(g, nullptr);
    EXPECT_EQ(wkbFlatten(g->getGeometryType()), type);
    if (type == wkbPolygon || type == wkbMultiPolygon) {
      EXPECT_TRUE(g->IsValid()) << "feature " << f->GetFID();
    }
  }
  EXPECT_EQ(fids.size(), static_cast<size_t>(l.GetFeatureCount()));
  l.ResetReading();
}

TEST(OgrExport, RoomInGeoPackage) {
  const Map m = room();
  const Scene s = room_scene();
  const std::string path = scratch("room.gpkg");
  OgrExportOptions o;
  o.map_name = "room";
  {
    OgrExport e(path, o);
    e.add_map(m);
    e.add_scene(s);
    e.close();
  }
  test::Dataset ds = open_vector(path);
  ASSERT_TRUE(ds);
  auto layers = layers_of(*ds);
  for (const char* name : {"border", "segments", "obstacles", "objects", "object_elements", "avoided_areas"})
    ASSERT_TRUE(layers.count(name)) << name;
  for (auto& [name, l] : layers) {
    expect_clean_layer(*l);
    // No georeference: an engineering CRS in metres named after the map.
    const OGRSpatialReference* srs = l->GetSpatialRef();
    ASSERT_NE(srs, nullptr) << name;
    EXPECT_TRUE(srs->IsLocal()) << name;
  }
  // The segments, in map order, at the map's coordinates.
  OGRLayer& seg = *layers.at("segments");
  ASSERT_EQ(seg.GetFeatureCount(), static_cast<GIntBig>(m.segment_count()));
  seg.ResetReading();
  for (const Obstacle& ob : m.obstacles) {
    for (const Segment& sg : ob.segments) {
      std::unique_ptr<OGRFeature> f(seg.GetNextFeature());
      ASSERT_TRUE(f);
      const OGRLineString* l = f->GetGeometryRef()->toLineString();
      ASSERT_EQ(l->getNumPoints(), 2);
      EXPECT_EQ(l->getX(0), sg.a.x);
      EXPECT_EQ(l->getY(0), sg.a.y);
      EXPECT_EQ(l->getX(1), sg.b.x);
      EXPECT_EQ(l->getY(1), sg.b.y);
      EXPECT_EQ(f->GetFieldAsInteger("obstacle_id"), ob.id);
      EXPECT_EQ(f->GetFieldAsDouble("h"), sg.h);
    }
  }
  // One feature per object; the example room has objects whose elements, as one
  // MultiPolygon, GEOS finds invalid (overlapping parts): the union made them valid.
  EXPECT_EQ(layers.at("objects")->GetFeatureCount(), static_cast<GIntBig>(s.objects.size()));
  size_t invalid_as_parts = 0, elements = 0;
  CPLPushErrorHandler(CPLQuietErrorHandler);  // GEOS says why each is invalid
  for (const EnvObject& ob : s.objects) {
    OGRMultiPolygon mp;
    for (const Element& el : ob.elements) {
      auto* ring = new OGRLinearRing;
      for (Point p : el.footprint) ring->addPoint(p.x, p.y);
      ring->closeRings();
      auto* poly = new OGRPolygon;
      poly->addRingDirectly(ring);
      mp.addGeometryDirectly(poly);
      ++elements;
    }
    invalid_as_parts += !mp.IsValid();
  }
  CPLPopErrorHandler();
  EXPECT_EQ(invalid_as_parts, 7u);
  EXPECT_EQ(layers.at("object_elements")->GetFeatureCount(), static_cast<GIntBig>(elements));
  EXPECT_EQ(layers.at("avoided_areas")->GetFeatureCount(), static_cast<GIntBig>(s.avoided.size()));
}

TEST(OgrExport, TheCrsIsTheBaseWhenTheMapFrameIsIt) {
  MapGeoref g;
  g.crs = "EPSG:26910";
  OgrExportOptions o;
  o.map_name = "utm";
  o.georef = g;
  const std::string path = scratch("utm.gpkg");
  {
    OgrExport e(path, o);
    e.add_map(room());
    e.close();
  }
  OGRSpatialReference utm;
  utm.importFromEPSG(26910);
  test::Dataset ds = open_vector(path);
  ASSERT_TRUE(ds);
  for (auto& [name, l] : layers_of(*ds)) {
    ASSERT_NE(l->GetSpatialRef(), nullptr) << name;
    EXPECT_TRUE(l->GetSpatialRef()->IsSame(&utm)) << name;
  }
}

MapGeoref rotated_utm() {
  MapGeoref g;
  g.crs = "EPSG:26910";
  g.tx = 491234.5;
  g.ty = 5457321.25;
  g.rotation = 0.4;
  g.scale = 1;
  return g;
}

Point by_hand(const MapGeoref& g, Point m) {
  const double c = std::cos(g.rotation), s = std::sin(g.rotation);
  return {g.tx + g.scale * (c * m.x - s * m.y), g.ty + g.scale * (s * m.x + c * m.y)};
}

TEST(OgrExport, ARotatedFrameIsLocalAndBaseOrWgs84Transform) {
  const Map m = room();
  const MapGeoref g = rotated_utm();
  OgrExportOptions o;
  o.map_name = "rot";
  o.georef = g;
  o.only_layers = {"segments"};
  const std::string local = scratch("rot_map.gpkg"), base = scratch("rot_base.gpkg"), wgs = scratch("rot_wgs.gpkg");
  for (auto [path, crs] : {std::pair{local, ExportCrs::Map}, {base, ExportCrs::Base}, {wgs, ExportCrs::Wgs84}}) {
    o.crs = crs;
    OgrExport e(path, o);
    e.add_map(m);
    e.close();
  }
  test::Dataset dl = open_vector(local), db = open_vector(base), dw = open_vector(wgs);
  ASSERT_TRUE(dl && db && dw);
  EXPECT_EQ(dl->GetLayerCount(), 1);  // only_layers
  EXPECT_TRUE(dl->GetLayer(0)->GetSpatialRef()->IsLocal());
  OGRSpatialReference utm, wgs84;
  utm.importFromEPSG(26910);
  wgs84.importFromEPSG(4326);
  wgs84.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);  // as OGR's readers give layers
  EXPECT_TRUE(db->GetLayer(0)->GetSpatialRef()->IsSame(&utm));
  EXPECT_TRUE(dw->GetLayer(0)->GetSpatialRef()->IsSame(&wgs84));
  const test::ProjToWgs84 proj("EPSG:26910");
  ASSERT_TRUE(proj.ok());
  OGRLayer *lb = db->GetLayer(0), *lw = dw->GetLayer(0);
  for (const Obstacle& ob : m.obstacles) {
    for (const Segment& sg : ob.segments) {
      std::unique_ptr<OGRFeature> fb(lb->GetNextFeature()), fw(lw->GetNextFeature());
      ASSERT_TRUE(fb && fw);
      const OGRLineString *b = fb->GetGeometryRef()->toLineString(), *w = fw->GetGeometryRef()->toLineString();
      const Point expect_b = by_hand(g, sg.a), expect_w = proj(expect_b);
      EXPECT_NEAR(b->getX(0), expect_b.x, 1e-6);
      EXPECT_NEAR(b->getY(0), expect_b.y, 1e-6);
      EXPECT_LT(test::ground_metres({w->getX(0), w->getY(0)}, expect_w), 1e-3);
    }
  }
}

TEST(OgrExport, TopologyAndTracks) {
  TopoGraph g;
  g.add_node({1, {0, 0}, "dock"});
  g.add_node({2, {3, 4}, ""});
  g.add_edge({1, 2});
  std::vector<Track> tracks{{"r1", {{"2026-12-02T00:36:02.25Z", {1, 1}, 0.5, 0.2}, {"2026-12-02T00:36:03Z", {2, 1}, 0.6, 0.3}}}};
  OgrExportOptions o;
  o.map_name = "lab";
  const std::string path = scratch("lab.gpkg");
  {
    OgrExport e(path, o);
    e.add_topology(g);
    e.add_tracks(tracks);
    e.close();
  }
  test::Dataset ds = open_vector(path);
  ASSERT_TRUE(ds);
  auto layers = layers_of(*ds);
  for (auto& [name, l] : layers) expect_clean_layer(*l);
  ASSERT_TRUE(layers.count("topo_nodes") && layers.count("topo_edges") && layers.count("trajectory_points") &&
              layers.count("trajectories"));
  EXPECT_EQ(layers.at("topo_nodes")->GetFeatureCount(), 2);
  std::unique_ptr<OGRFeature> e(layers.at("topo_edges")->GetNextFeature());
  ASSERT_TRUE(e);
  EXPECT_DOUBLE_EQ(e->GetFieldAsDouble("length"), 5.0);
  EXPECT_TRUE(e->IsFieldNull(e->GetFieldIndex("max_speed")));  // infinite: no limit
  // Times come back as UTC date-times (OGR's TZFlag 100).
  OGRLayer& pts = *layers.at("trajectory_points");
  std::unique_ptr<OGRFeature> p(pts.GetNextFeature());
  ASSERT_TRUE(p);
  int y, mo, d, h, mi, tz;
  float s;
  ASSERT_TRUE(p->GetFieldAsDateTime(p->GetFieldIndex("t"), &y, &mo, &d, &h, &mi, &s, &tz));
  EXPECT_EQ(y, 2026);
  EXPECT_EQ(mo, 12);
  EXPECT_EQ(d, 2);
  EXPECT_EQ(h, 0);
  EXPECT_EQ(mi, 36);
  EXPECT_FLOAT_EQ(s, 2.25f);
  EXPECT_EQ(tz, 100);
  EXPECT_DOUBLE_EQ(p->GetFieldAsDouble("theta"), 0.5);
  EXPECT_DOUBLE_EQ(p->GetFieldAsDouble("v"), 0.2);
  EXPECT_EQ(layers.at("trajectories")->GetFeatureCount(), 1);
}

TEST(OgrExport, FlatGeobufDirectoryHoldsEveryLayer) {
  const std::string dir = scratch("room_fgb");
  std::filesystem::remove_all(dir);
  OgrExportOptions o;
  o.format = "fgb";
  o.map_name = "room";
  {
    OgrExport e(dir, o);
    e.add_map(room());
    e.add_scene(room_scene());
    e.close();
  }
  test::Dataset ds = open_vector(dir);
  ASSERT_TRUE(ds);
  auto layers = layers_of(*ds);
  EXPECT_TRUE(layers.count("segments") && layers.count("objects"));
  for (auto& [name, l] : layers) {
    const OGRwkbGeometryType type = wkbFlatten(l->GetGeomType());
    for (auto& f : *l) {
      if (type == wkbPolygon || type == wkbMultiPolygon) {
        EXPECT_TRUE(f->GetGeometryRef()->IsValid()) << name;
      }
    }
  }
}

TEST(OgrExport, RefusesWhatItCannotWrite) {
  EXPECT_THROW(ogr_driver_for("no-such-driver"), BadInput);
  EXPECT_THROW(ogr_driver_for("PNG"), BadInput);  // raster only
  EXPECT_EQ(ogr_driver_for("gpkg"), "GPKG");
  EXPECT_EQ(ogr_driver_for("fgb"), "FlatGeobuf");
  OgrExportOptions o;
  o.crs = ExportCrs::Wgs84;  // without a georeference
  EXPECT_THROW(OgrExport(scratch("none.gpkg"), o), BadInput);
  o.crs = ExportCrs::Map;
  o.format = "GeoJSON";  // one layer per file
  OgrExport e(scratch("two.geojson"), o);
  EXPECT_THROW(e.add_map(room()), BadInput);
  std::vector<Track> bad{{"r1", {{"2026-12-02 00:36:02", {1, 1}, 0, 0}}}};
  OgrExport t(scratch("bad.gpkg"), OgrExportOptions{});
  EXPECT_THROW(t.add_tracks(bad), BadInput);  // no zone
}

}  // namespace
}  // namespace fleetmap
