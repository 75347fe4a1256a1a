// Imports of real GIS files (../shared/maps/gis/README.md), each checked against OGR's
// own reading of the same file and brute-force counts, never against the importer.
#include "common/gis/ogr_import.h"

#include <cpl_conv.h>
#include <gtest/gtest.h>
#include <ogrsf_frmts.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>

#include "common/core/error.h"

namespace fleetmap {
namespace {

std::string gis(const std::string& f) { return std::string(FLEETMAP_REAL_MAPS) + "/gis/" + f; }
const std::string kUbcGpkg = "ubc-vancouver/buildings-2019/ubcv_buildings_gpkg.gpkg";
const std::string kUbcJson = "ubc-vancouver/buildings-2019/ubcv_buildings.geojson";
const std::string kCampus = "osm-montgomery-college-rockville/campus.osm";
const std::string kDxf = "dxf-openindoor-clermont/plan.dxf";

GDALDatasetUniquePtr open(const std::string& path) {
  GDALAllRegister();
  GDALDatasetUniquePtr ds(GDALDataset::Open(path.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY));
  if (!ds) ADD_FAILURE() << "OGR cannot open " << path;
  return ds;
}

// Segments a ring or line gives: its vertices - 1, less the repeated consecutive ones.
size_t segments_of(const OGRLineString& ls) {
  size_t n = 0;
  for (int i = 1; i < ls.getNumPoints(); ++i)
    if (ls.getX(i) != ls.getX(i - 1) || ls.getY(i) != ls.getY(i - 1)) ++n;
  return n;
}

// Relative to the first vertex: UTM coordinates (5e6 m) would cancel out in the cross products.
double signed_area(const Obstacle& o) {
  const Point r = o.segments[0].a;
  double a = 0;
  for (const Segment& s : o.segments) a += cross(s.a - r, s.b - r);
  return a / 2;
}

Point centroid(const std::vector<const Obstacle*>& rings) {
  const Point r = rings[0]->segments[0].a;
  double a = 0, cx = 0, cy = 0;
  for (const Obstacle* o : rings)
    for (const Segment& s : o->segments) {
      const Point p = s.a - r, q = s.b - r;
      const double c = cross(p, q);
      a += c;
      cx += (p.x + q.x) * c;
      cy += (p.y + q.y) * c;
    }
  return r + Point{cx / (3 * a), cy / (3 * a)};
}

nlohmann::json semantic(const Obstacle& o) { return nlohmann::json::parse(o.semantic); }

struct Expected {
  size_t segments = 0, outer = 0, holes = 0;
  OGREnvelope env;
};

Expected read_polygons(OGRLayer& layer) {
  Expected e;
  for (auto& f : layer) {
    const OGRGeometry* g = f->GetGeometryRef();
    std::unique_ptr<OGRGeometry> lin(g->getLinearGeometry());
    OGREnvelope env;
    lin->getEnvelope(&env);
    e.env.Merge(env);
    auto polygon = [&](const OGRPolygon& p) {
      ++e.outer;
      e.holes += p.getNumInteriorRings();
      for (const OGRLinearRing* r : p) e.segments += segments_of(*r);
    };
    if (wkbFlatten(lin->getGeometryType()) == wkbPolygon) polygon(*lin->toPolygon());
    else
      for (const OGRGeometry* p : *lin->toMultiPolygon()) polygon(*p->toPolygon());
  }
  return e;
}

TEST(OgrImport, UbcGeoPackageInUtm) {
  OgrImportOptions opt;
  opt.layers = {"ubcv_buildings"};
  const OgrImport r = import_ogr(gis(kUbcGpkg), opt);
  auto ds = open(gis(kUbcGpkg));
  const Expected e = read_polygons(*ds->GetLayerByName("ubcv_buildings"));
  ASSERT_TRUE(r.georef);
  EXPECT_EQ(r.georef->crs, "EPSG:26910");
  EXPECT_TRUE(r.georef->frame_is_crs());
  EXPECT_EQ(r.report.layers.at("ubcv_buildings").read, 270u);
  EXPECT_EQ(r.report.layers.at("ubcv_buildings").kept, 270u);
  EXPECT_EQ(r.map.segment_count(), e.segments);
  EXPECT_EQ(r.map.obstacles.size(), e.outer + e.holes);
  size_t ccw = 0, cw = 0;
  for (const Obstacle& o : r.map.obstacles) {
    EXPECT_EQ(o.type, ShapeType::ClosedPolygon);
    (signed_area(o) > 0 ? ccw : cw)++;
    for (const Segment& s : o.segments) EXPECT_EQ(s.h, 3);  // the plain rule's default: 2019 has no heights
  }
  // seed 000 section 3: buildings counter-clockwise (free space outside), holes clockwise
  EXPECT_EQ(ccw, e.outer);
  EXPECT_EQ(cw, e.holes);
  EXPECT_DOUBLE_EQ(r.report.extent.xmin, e.env.MinX);
  EXPECT_DOUBLE_EQ(r.report.extent.ymax, e.env.MaxY);
  EXPECT_DOUBLE_EQ(r.map.border.mx1, e.env.MinX - 2);
}

TEST(OgrImport, CurvesAreLinearised) {
  OgrImportOptions opt;
  opt.layers = {"ubcv_buildings_uc"};
  const OgrImport r = import_ogr(gis(kUbcGpkg), opt);
  auto ds = open(gis(kUbcGpkg));
  double area = 0;
  bool curve = false;
  for (auto& f : *ds->GetLayerByName("ubcv_buildings_uc")) {
    curve |= f->GetGeometryRef()->hasCurveGeometry() == TRUE;
    area += OGR_G_Area(OGRGeometry::ToHandle(f->GetGeometryRef()));
  }
  ASSERT_TRUE(curve);
  double ours = 0;
  for (const Obstacle& o : r.map.obstacles) ours += signed_area(o);
  // 4-degree steps on the arcs: the chords cut off well under 0.1 % of the area.
  EXPECT_NEAR(ours, area, area * 1e-3);
}

TEST(OgrImport, UbcGeoPackageAndGeoJsonAgreeInOneFrame) {
  OgrImportOptions utm;
  utm.layers = {"ubcv_buildings"};
  const OgrImport a = import_ogr(gis(kUbcGpkg), utm);
  OgrImportOptions wgs;
  wgs.frame = a.georef;
  const OgrImport b = import_ogr(gis(kUbcJson), wgs);
  auto by_building = [](const Map& m) {
    std::map<std::string, std::vector<const Obstacle*>> out;
    for (const Obstacle& o : m.obstacles) out[semantic(o).at("BLDG_ID").dump()].push_back(&o);
    return out;
  };
  const auto ma = by_building(a.map), mb = by_building(b.map);
  ASSERT_EQ(ma.size(), 270u);
  std::vector<double> d;
  for (const auto& [id, rings] : ma) {
    ASSERT_TRUE(mb.count(id)) << id;
    d.push_back(distance(centroid(rings), centroid(mb.at(id))));
  }
  std::sort(d.begin(), d.end());
  // README: centroids within 1.4 mm median, 1.4 cm worst (the GeoJSON's rounding).
  EXPECT_LE(d[d.size() / 2], 0.01);
  EXPECT_LE(d.back(), 0.02);
}

TEST(OgrImport, OsmCampusBuildingsHeightsStepsAndObjects) {
  const OgrImport r = import_ogr(gis(kCampus));
  ASSERT_TRUE(r.georef);
  // Independent: GDAL's own OSM configuration and its SQLite dialect's hstore reader.
  auto ds = open(gis(kCampus));
  OGRLayer* q = ds->ExecuteSQL(
      "SELECT osm_id, osm_way_id, hstore_get_value(other_tags, 'height') AS height, "
      "hstore_get_value(other_tags, 'building:levels') AS levels FROM multipolygons WHERE building IS NOT NULL",
      nullptr, "SQLITE");
  ASSERT_TRUE(q);
  std::map<std::string, double> expected_h;  // osm id -> height
  for (auto& f : *q) {
    const std::string id = f->IsFieldSetAndNotNull(0) ? f->GetFieldAsString(0) : f->GetFieldAsString(1);
    double h = 6;  // the default_height of osm_default_rules
    if (f->IsFieldSetAndNotNull(2)) h = CPLAtof(f->GetFieldAsString(2));
    else if (f->IsFieldSetAndNotNull(3)) h = 3 * CPLAtof(f->GetFieldAsString(3));
    expected_h[id] = h;
  }
  ds->ReleaseResultSet(q);
  ASSERT_EQ(expected_h.size(), 73u);
  std::map<std::string, size_t> seen;
  size_t with_height = 0, stairs = 0;
  for (const Obstacle& o : r.map.obstacles) {
    if (o.type == ShapeType::Stairs) ++stairs;
    if (o.segments[0].semantic != "building") continue;
    const auto j = semantic(o);
    const std::string id = j.contains("osm_id") ? j["osm_id"].get<std::string>() : j["osm_way_id"].get<std::string>();
    ASSERT_TRUE(expected_h.count(id)) << id;
    ++seen[id];
    for (const Segment& s : o.segments) EXPECT_DOUBLE_EQ(s.h, expected_h[id]) << id;
    if (expected_h[id] != 6) ++with_height;
  }
  EXPECT_EQ(seen.size(), 73u);  // every building, clipped at <bounds> or whole
  EXPECT_GE(with_height, 23u);
  EXPECT_EQ(stairs, 13u);       // README: 13 steps
  EXPECT_GT(r.scene.objects.size(), 0u);
  // Clipped to <bounds> (README): the extent lies within it.
  ASSERT_TRUE(r.report.extent_wgs84);
  EXPECT_GE(r.report.extent_wgs84->first.lon, -77.16241 - 1e-6);
  EXPECT_LE(r.report.extent_wgs84->second.lon, -77.15458 + 1e-6);
  EXPECT_GE(r.report.extent_wgs84->first.lat, 39.09513 - 1e-6);
  EXPECT_LE(r.report.extent_wgs84->second.lat, 39.10149 + 1e-6);
  // The local TM origin at the kept extent's centre, rounded to 0.001 degree.
  EXPECT_NE(r.georef->crs.find("+proj=tmerc"), std::string::npos);
}

TEST(OgrImport, DxfInCentimetresBecomesMetres) {
  CPLSetConfigOption("DXF_ENCODING", "UTF-8");
  const OgrImport r = import_ogr(gis(kDxf));
  EXPECT_FALSE(r.georef);
  EXPECT_DOUBLE_EQ(r.report.unit_scale, 0.01);  // README: $INSUNITS = 5
  auto ds = open(gis(kDxf));
  OGRLayer* l = ds->GetLayer(0);
  size_t segments = 0, points = 0;
  std::map<std::string, size_t> layers;
  OGREnvelope lines;
  for (auto& f : *l) {
    ++layers[f->GetFieldAsString("Layer")];
    const OGRGeometry* g = f->GetGeometryRef();
    OGREnvelope e;
    g->getEnvelope(&e);
    if (wkbFlatten(g->getGeometryType()) != wkbPoint) lines.Merge(e);
    if (wkbFlatten(g->getGeometryType()) == wkbPoint) ++points;
    else if (wkbFlatten(g->getGeometryType()) == wkbLineString) segments += segments_of(*g->toLineString());
    else
      for (const OGRGeometry* p : *g->toMultiLineString()) segments += segments_of(*p->toLineString());
  }
  CPLSetConfigOption("DXF_ENCODING", nullptr);
  EXPECT_EQ(layers.at("ABY_Zone_ZIND"), 182u);  // the UTF-8 layer names, as the README lists them
  EXPECT_EQ(layers.at("Texte_Pièces"), 107u);
  EXPECT_EQ(r.map.segment_count(), segments);
  EXPECT_EQ(r.scene.objects.size(), points);
  Rect walls = Rect::none();
  for (const Obstacle& o : r.map.obstacles)
    for (const Segment& s : o.segments) {
      walls.extend(s.a);
      walls.extend(s.b);
    }
  EXPECT_NEAR(walls.xmin, lines.MinX * 0.01, 1e-9);
  EXPECT_NEAR(walls.xmax, lines.MaxX * 0.01, 1e-9);
  EXPECT_NEAR(walls.ymin, lines.MinY * 0.01, 1e-9);
  EXPECT_NEAR(walls.ymax, lines.MaxY * 0.01, 1e-9);
}

TEST(OgrImport, Ubc2026HeightsFromTheRulesFile) {
  const std::string file = gis("ubc-vancouver/current-2026/ubcv_buildings.geojson");
  OgrImportOptions opt;
  opt.rules = parse_import_rules(R"({"rules": [{"geometry": "polygon", "action": "closed", "tag": "building",
      "height": {"attribute": "BLDG_HEIGHT", "levels_attribute": "MAX_FLOORS", "level_height": 3.5, "default": 4}}]})",
                                 "test rules");
  const OgrImport r = import_ogr(file, opt);
  // OGR's reading: the height each building's segments must carry.
  auto ds = open(file);
  std::map<long long, double> expected;
  size_t rings = 0;
  for (auto& f : *ds->GetLayer(0)) {
    const int hi = f->GetFieldIndex("BLDG_HEIGHT"), li = f->GetFieldIndex("MAX_FLOORS");
    double h = 4;
    if (f->IsFieldSetAndNotNull(hi) && f->GetFieldAsDouble(hi) > 0) h = f->GetFieldAsDouble(hi);
    else if (f->IsFieldSetAndNotNull(li) && f->GetFieldAsInteger(li) > 0) h = 3.5 * f->GetFieldAsInteger(li);
    expected[f->GetFID()] = h;
    OGRGeometry* g = f->GetGeometryRef();
    if (wkbFlatten(g->getGeometryType()) == wkbPolygon) rings += 1 + g->toPolygon()->getNumInteriorRings();
    else
      for (const OGRGeometry* p : *g->toMultiPolygon()) rings += 1 + p->toPolygon()->getNumInteriorRings();
  }
  ASSERT_EQ(expected.size(), 443u);  // README
  EXPECT_EQ(r.map.obstacles.size(), rings);
  size_t measured = 0;
  for (const Obstacle& o : r.map.obstacles) {
    const long long fid = semantic(o).at("fid");
    for (const Segment& s : o.segments) EXPECT_DOUBLE_EQ(s.h, expected.at(fid)) << fid;
    if (semantic(o).contains("BLDG_HEIGHT")) ++measured;
  }
  EXPECT_GT(measured, 0u);
}

class TempFile {
 public:
  TempFile(const std::string& name, const std::string& text)
      : path_((std::filesystem::temp_directory_path() / (std::to_string(::getpid()) + "_" + name)).string()) {
    std::ofstream(path_) << text;
  }
  ~TempFile() { std::filesystem::remove(path_); }
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

const char* kBowtie = R"({"type": "FeatureCollection", "features": [
  {"type": "Feature", "id": 1, "properties": {"name": "good"},
   "geometry": {"type": "Polygon", "coordinates": [[[0, 0], [10, 0], [10, 10], [0, 10], [0, 0]]]}},
  {"type": "Feature", "id": 2, "properties": {"name": "bowtie"},
   "geometry": {"type": "Polygon", "coordinates": [[[20, 0], [30, 10], [30, 0], [20, 10], [20, 0]]]}}]})";

TEST(OgrImport, GeoJsonWithCrsOption) {
  const TempFile f("square.geojson", std::string(kBowtie).substr(0, std::string(kBowtie).find(",\n  {\"type\": \"Feature\", \"id\": 2")) + "]}");
  OgrImportOptions opt;
  opt.crs = "EPSG:32631";  // the file's coordinates taken as UTM 31N metres
  const OgrImport r = import_ogr(f.path(), opt);
  ASSERT_EQ(r.map.obstacles.size(), 1u);
  EXPECT_EQ(r.georef->crs, "EPSG:32631");
  EXPECT_EQ(r.map.segment_count(), 4u);
  EXPECT_GT(signed_area(r.map.obstacles[0]), 0);
  EXPECT_EQ(semantic(r.map.obstacles[0]).at("name"), "good");
}

TEST(OgrImport, InvalidPolygonRefusedNamesTheFeatureOrRepaired) {
  const TempFile f("bowtie.geojson", kBowtie);
  OgrImportOptions opt;
  opt.crs = "EPSG:32631";
  opt.invalid = InvalidPolicy::Refuse;
  try {
    import_ogr(f.path(), opt);
    FAIL() << "an invalid polygon was imported";
  } catch (const BadInput& e) {
    EXPECT_NE(std::string(e.what()).find("feature 2"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("elf-intersection"), std::string::npos) << e.what();  // GEOS's reason
  }
  opt.invalid = InvalidPolicy::Repair;
  const OgrImport r = import_ogr(f.path(), opt);
  EXPECT_EQ(r.report.layers.begin()->second.repaired, 1u);
  ASSERT_EQ(r.map.obstacles.size(), 3u);  // the square and the bowtie's two triangles
  for (const Obstacle& o : r.map.obstacles) EXPECT_GT(signed_area(o), 0);
}

TEST(OgrImport, EveryAttributeKeptInTheSemanticEvenPastOneKilobyte) {
  const std::string long_text = std::string(1500, 'x') + "; #1 100%";
  const TempFile f("long.geojson", R"({"type": "FeatureCollection", "features": [{"type": "Feature", "id": 4,
    "properties": {"name": ")" + long_text + R"(", "levels": 2, "kind": "hall"},
    "geometry": {"type": "Polygon", "coordinates": [[[0, 0], [0, 10], [10, 10], [10, 0], [0, 0]]]}}]})");
  OgrImportOptions opt;
  opt.crs = "EPSG:32631";
  const OgrImport r = import_ogr(f.path(), opt);
  ASSERT_EQ(r.map.obstacles.size(), 1u);
  const Obstacle& o = r.map.obstacles[0];
  EXPECT_GT(o.semantic.size(), 1024u);
  EXPECT_EQ(o.semantic.find_first_of(";#%"), std::string::npos);  // seed format delimiters escaped
  const auto j = semantic(o);
  EXPECT_EQ(j.at("name"), long_text);
  EXPECT_EQ(j.at("kind"), "hall");
  EXPECT_EQ(j.at("levels"), 2);
  for (const Segment& s : o.segments) EXPECT_EQ(s.h, 6);  // the plain rule: levels x 3 m
}

TEST(OgrImport, TruncatedGeoJsonImportsNothing) {
  const TempFile f("truncated.geojson", std::string(kBowtie).substr(0, 150));
  EXPECT_THROW(import_ogr(f.path()), FileFormatError);
}

TEST(OgrImport, UnknownLayerIsNamed) {
  OgrImportOptions opt;
  opt.layers = {"roads"};
  try {
    import_ogr(gis(kUbcGpkg), opt);
    FAIL();
  } catch (const BadInput& e) {
    EXPECT_NE(std::string(e.what()).find("ubcv_buildings_uc"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace fleetmap
