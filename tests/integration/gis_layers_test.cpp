// The database as GIS layers (protocol/gis_layers.h, docs/gis-layers.md), read by the
// real GDAL tools as the inspector: ogrinfo lists every layer with its SRS, FID column,
// feature count and extent; ogr2ogr -f GPKG keeps the CRS. Checked against SQL counts
// and extents of the fleet tables, against GeoTransform (PROJ on the base CRS and the
// similarity, not the WKT under test) for georeferenced frames, and OGR's own reading.
#include <gdal_priv.h>
#include <ogr_spatialref.h>
#include <ogrsf_frmts.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <regex>
#include <set>
#include <vector>

#include <gtest/gtest.h>

#include "common/gis/geo_transform.h"
#include "common/gis/map_frame_crs.h"
#include "common/map/map.h"
#include "protocol/gis_layers.h"
#include "protocol/map_store.h"
#include "tests/integration/server_fixture.h"
#include "tests/integration/test_db.h"

namespace fleetmap::test {
namespace {

const std::string kRoom = "gis_room";      // maps/example-room.map with its objects
const std::string kCampus = "gis_campus";  // maps/example-campus.map: every shape type
const std::string kUtm = "gis_utm";

// Runs a shell command (a GDAL tool), returning its standard output; stderr goes to a file.
std::string shell(const std::string& cmd, int* exit_code = nullptr) {
  const std::string out = temp_path("gis-shell.out"), err = temp_path("gis-shell.err");
  const int status = std::system((cmd + " >" + out + " 2>" + err).c_str());
  if (exit_code) *exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return read_file(out);
}

// The layers database as the inspector reaches it over TCP, as a GIS tool would.
std::string connection() {
  const DbSettings s = tcp_settings(Role::Inspector);
  return "'MYSQL:" + s.database + "_gis,host=" + s.host + ",port=" + std::to_string(s.port) + ",user=" + s.user +
         ",password=" + s.password + "'";
}

std::string layer(const std::string& map, const std::string& name) { return map + ":" + name; }

long long map_id(const std::string& name) { return scalar("SELECT id FROM maps WHERE name = '" + name + "'"); }

struct LayerSummary {
  bool found = false;
  std::string geometry, fid_column, srs_wkt;
  long long count = -1;
  std::array<double, 4> extent{};  // minx, miny, maxx, maxy
};

LayerSummary parse_summary(const std::string& text, const std::string& table) {
  LayerSummary s;
  std::smatch m;
  s.found = std::regex_search(text, m, std::regex("Layer name: (.*)\n")) && m[1] == table;
  if (std::regex_search(text, m, std::regex("Geometry: (.*)\n"))) s.geometry = m[1];
  if (std::regex_search(text, m, std::regex("FID Column = (.*)\n"))) s.fid_column = m[1];
  if (std::regex_search(text, m, std::regex("Feature Count: (\\d+)"))) s.count = std::stoll(m[1]);
  const std::string num = "(-?[0-9.eE+-]+)";
  if (std::regex_search(text, m, std::regex("Extent: \\(" + num + ", " + num + "\\) - \\(" + num + ", " + num + "\\)")))
    s.extent = {std::stod(m[1]), std::stod(m[2]), std::stod(m[3]), std::stod(m[4])};
  const size_t a = text.find("Layer SRS WKT:\n"), b = text.find("Data axis to CRS axis mapping");
  if (a != std::string::npos && b != std::string::npos) s.srs_wkt = text.substr(a + 15, b - a - 15);
  return s;
}

// ogrinfo -so on some layers (one run), parsed per layer.
std::map<std::string, LayerSummary> summaries(const std::vector<std::string>& tables) {
  std::string cmd = "ogrinfo -ro -so " + connection();
  for (const std::string& t : tables) cmd += " '" + t + "'";
  int rc = 0;
  const std::string text = shell(cmd, &rc);
  std::map<std::string, LayerSummary> out;
  if (rc != 0) return out;
  size_t at = text.find("\nLayer name: ");
  while (at != std::string::npos) {
    const size_t next = text.find("\nLayer name: ", at + 1);
    const std::string part = text.substr(at + 1, next == std::string::npos ? std::string::npos : next - at - 1);
    std::smatch m;
    if (std::regex_search(part, m, std::regex("Layer name: (.*)\n"))) out[m[1]] = parse_summary(part, m[1]);
    at = next;
  }
  return out;
}

LayerSummary summary(const std::string& table) {
  auto all = summaries({table});
  return all.count(table) ? all[table] : LayerSummary{};
}

// The FIDs ogrinfo prints for some layers (one run), per layer in reading order.
std::map<std::string, std::vector<long long>> fids(const std::vector<std::string>& tables) {
  std::string cmd = "ogrinfo -ro -q " + connection();
  for (const std::string& t : tables) cmd += " '" + t + "'";
  const std::string text = shell(cmd);
  std::map<std::string, std::vector<long long>> out;
  const std::regex re("OGRFeature\\(([^)]*)\\):(\\d+)");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), re); it != std::sregex_iterator(); ++it)
    out[(*it)[1]].push_back(std::stoll((*it)[2]));
  return out;
}

std::unique_ptr<OGRSpatialReference> srs(const std::string& wkt) {
  auto s = std::make_unique<OGRSpatialReference>();
  s->SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  EXPECT_EQ(s->importFromWkt(wkt.c_str()), OGRERR_NONE) << wkt;
  return s;
}

// Map frame -> WGS 84 through an SRS as OGR reads it.
std::array<double, 2> to_wgs84(const OGRSpatialReference& from, double x, double y) {
  OGRSpatialReference wgs84;
  wgs84.importFromEPSG(4326);
  wgs84.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  std::unique_ptr<OGRCoordinateTransformation> t(OGRCreateCoordinateTransformation(&from, &wgs84));
  EXPECT_TRUE(t);
  if (!t) return {NAN, NAN};
  EXPECT_TRUE(t->Transform(1, &x, &y));
  return {x, y};
}

// The segments' extent by SQL: what the segments layer must report.
std::array<double, 4> segment_extent(long long id) {
  const std::string m = " FROM segments WHERE map_id = " + std::to_string(id);
  auto d = [&](const std::string& e) {
    auto c = admin();
    mysqlpp::Query q = c->query("SELECT " + e + m);
    return std::stod(std::string(q.store()[0][0]));
  };
  return {d("MIN(LEAST(ax, bx))"), d("MIN(LEAST(ay, `by`))"), d("MAX(GREATEST(ax, bx))"), d("MAX(GREATEST(ay, `by`))")};
}

// Imports what a test needs once per test run (each test is its own process under
// CTest): the maps stay in the test database, and every command below publishes.
void import_once(const std::string& name, const std::string& file) {
  if (scalar("SELECT COUNT(*) FROM maps WHERE name = '" + name + "'") > 0) return;
  const RunResult r = run("fleetmap", "map import " + source_path(file) + " --name " + name + " --replace");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err.find("warning"), std::string::npos) << r.err;
}

class GisLayersTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    GDALAllRegister();
    import_once(kCampus, "maps/example-campus.map");
    import_once(kRoom, "maps/example-room.map");
    if (scalar("SELECT COUNT(*) FROM env_objects o JOIN maps m ON m.id = o.map_id WHERE m.name = '" + kRoom + "'") == 0) {
      const RunResult r =
          run("fleetmap", "objects import " + kRoom + " " + source_path("maps/example-room.geojson") + " --replace");
      ASSERT_EQ(r.exit_code, 0) << r.err;
      EXPECT_EQ(r.err.find("warning"), std::string::npos) << r.err;
    }
    // Unreferenced, whatever an earlier run left, and published anew by this build.
    for (const std::string& map : {kRoom, kCampus}) {
      const RunResult r = run("fleetmap", "map georef " + map + " --clear");
      ASSERT_EQ(r.exit_code, 0) << r.err;
      EXPECT_EQ(r.err.find("warning"), std::string::npos) << r.err;
    }
  }
};

TEST_F(GisLayersTest, OgrinfoListsEveryLayerWithItsSrsFidCountAndExtent) {
  const std::string listing = shell("ogrinfo -ro " + connection());
  for (const std::string& map : {kRoom, kCampus})
    for (const std::string& l : GisLayers::map_layer_names())
      EXPECT_NE(listing.find(": " + layer(map, l) + " ("), std::string::npos) << map << " " << l << "\n" << listing;
  // Fleet tables and the metadata tables are no layers of the GIS database.
  EXPECT_EQ(listing.find("geometry_columns"), std::string::npos);
  EXPECT_EQ(listing.find(": segments"), std::string::npos);

  struct Expect {
    std::string map, layer, geometry;
    long long count;
  };
  const std::string room = std::to_string(map_id(kRoom)), campus = std::to_string(map_id(kCampus));
  const std::vector<Expect> expected = {
      {kRoom, "segments", "Line String", scalar("SELECT COUNT(*) FROM segments WHERE map_id = " + room)},
      {kCampus, "segments", "Line String", scalar("SELECT COUNT(*) FROM segments WHERE map_id = " + campus)},
      {kCampus, "obstacles", "Polygon", scalar("SELECT COUNT(*) FROM obstacles WHERE st IN (1, 3, 6) AND map_id = " + campus)},
      {kCampus, "open_obstacles", "Multi Line String",
       scalar("SELECT COUNT(*) FROM obstacles WHERE st NOT IN (1, 3, 6) AND map_id = " + campus)},
      {kRoom, "border", "Polygon", 1},
      {kRoom, "bounds", "Polygon", 1},
      {kRoom, "objects", "Polygon", scalar("SELECT COUNT(*) FROM object_elements WHERE map_id = " + room)},
      {kRoom, "avoided_areas", "Polygon", scalar("SELECT COUNT(*) FROM avoided_areas WHERE map_id = " + room)},
  };
  std::vector<std::string> tables;
  for (const Expect& e : expected) tables.push_back(layer(e.map, e.layer));
  auto got = summaries(tables);
  for (const Expect& e : expected) {
    SCOPED_TRACE(e.map + ":" + e.layer);
    const LayerSummary& s = got[layer(e.map, e.layer)];
    ASSERT_TRUE(s.found);
    EXPECT_EQ(s.geometry, e.geometry);
    EXPECT_EQ(s.fid_column, "fid");
    EXPECT_EQ(s.count, e.count);
    EXPECT_GT(s.count, 0);
    // An unreferenced map frame: an engineering (local) CRS in metres, x east, y north.
    auto crs = srs(s.srs_wkt);
    EXPECT_TRUE(crs->IsLocal()) << s.srs_wkt;
    EXPECT_DOUBLE_EQ(crs->GetLinearUnits(), 1.0);
  }
  for (const std::string& map : {kRoom, kCampus}) {
    const std::array<double, 4> seg = segment_extent(map_id(map));
    const LayerSummary& segments = got[layer(map, "segments")];
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(segments.extent[i], seg[i], 1e-6) << map << " " << i;
  }
  const MapInfo info = [] {
    auto c = connect_as(Role::Operator);
    return MapStore(*c).info(kRoom);
  }();
  const LayerSummary& border = got[layer(kRoom, "border")];
  EXPECT_NEAR(border.extent[0], std::min(info.border.mx1, info.border.mx4), 1e-9);
  EXPECT_NEAR(border.extent[1], std::min(info.border.my1, info.border.my4), 1e-9);
  EXPECT_NEAR(border.extent[2], std::max(info.border.mx1, info.border.mx4), 1e-9);
  EXPECT_NEAR(border.extent[3], std::max(info.border.my1, info.border.my4), 1e-9);
}

TEST_F(GisLayersTest, FidsAreTheRowsIdsStableAndUnique) {
  const std::vector<std::string> tables = {layer(kRoom, "segments"), layer(kRoom, "objects"),
                                           layer(kRoom, "avoided_areas"), layer(kCampus, "open_obstacles")};
  const auto first = fids(tables), second = fids(tables);
  for (const std::string& t : tables) {
    SCOPED_TRACE(t);
    ASSERT_TRUE(first.count(t));
    EXPECT_EQ(first.at(t), second.at(t));
    EXPECT_EQ(std::set<long long>(first.at(t).begin(), first.at(t).end()).size(), first.at(t).size());
  }
  // Segments carry the fleet table's own ids.
  const std::string mid = std::to_string(map_id(kRoom));
  const std::vector<long long>& seg = first.at(layer(kRoom, "segments"));
  EXPECT_EQ(*std::min_element(seg.begin(), seg.end()), scalar("SELECT MIN(id) FROM segments WHERE map_id = " + mid));
  EXPECT_EQ(*std::max_element(seg.begin(), seg.end()), scalar("SELECT MAX(id) FROM segments WHERE map_id = " + mid));
  // Publishing again (objects import --replace) keeps every FID of an unchanged layer.
  const RunResult r =
      run("fleetmap", "objects import " + kRoom + " " + source_path("maps/example-room.geojson") + " --replace");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto third = fids({layer(kRoom, "segments"), layer(kRoom, "objects")});
  EXPECT_EQ(third.at(layer(kRoom, "segments")), seg);
  EXPECT_EQ(static_cast<long long>(third.at(layer(kRoom, "objects")).size()),
            scalar("SELECT COUNT(*) FROM object_elements WHERE map_id = " + mid));
}

// An open obstacle is its segments, one part each: same count and length as by SQL.
TEST_F(GisLayersTest, OpenObstaclesAreTheirSegmentsAsLines) {
  const std::string out = temp_path("gis-campus.gpkg");
  std::remove(out.c_str());
  int rc = 0;
  shell("ogr2ogr -f GPKG " + out + " " + connection() + " '" + layer(kCampus, "open_obstacles") + "'", &rc);
  ASSERT_EQ(rc, 0) << read_file(temp_path("gis-shell.err"));
  std::unique_ptr<GDALDataset> ds(GDALDataset::Open(out.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY));
  ASSERT_TRUE(ds);
  const std::string mid = std::to_string(map_id(kCampus));
  size_t n = 0;
  for (auto& f : *ds->GetLayer(0)) {
    const std::string ord = std::to_string(f->GetFieldAsInteger64("ord"));
    auto c = admin();
    mysqlpp::Query q = c->query("SELECT SUM(SQRT(POW(bx - ax, 2) + POW(`by` - ay, 2))), COUNT(*) FROM segments"
                                " WHERE map_id = " + mid + " AND obstacle_ord = " + ord);
    const mysqlpp::Row row = q.store()[0];
    const OGRMultiLineString* lines = f->GetGeometryRef()->toMultiLineString();
    EXPECT_NEAR(lines->get_Length(), std::stod(std::string(row[0])), 1e-9) << "obstacle ord " << ord;
    EXPECT_EQ(lines->getNumGeometries(), std::stoi(std::string(row[1])));
    ++n;
  }
  EXPECT_EQ(static_cast<long long>(n), scalar("SELECT COUNT(*) FROM obstacles WHERE st NOT IN (1, 3, 6) AND map_id = " + mid));
}

// Through ogr2ogr into a GeoPackage and read back by OGR: the polygons are the obstacles'
// rings (area by the shoelace formula over the SQL segments), the CRS survives.
TEST_F(GisLayersTest, Ogr2ogrGpkgKeepsCrsAndGeometry) {
  const std::string out = temp_path("gis-room.gpkg");
  std::remove(out.c_str());
  int rc = 0;
  shell("ogr2ogr -f GPKG " + out + " " + connection() + " '" + layer(kRoom, "obstacles") + "' '" +
            layer(kRoom, "segments") + "'",
        &rc);
  ASSERT_EQ(rc, 0) << read_file(temp_path("gis-shell.err"));
  std::unique_ptr<GDALDataset> ds(GDALDataset::Open(out.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY));
  ASSERT_TRUE(ds);
  OGRLayer* obstacles = ds->GetLayerByName(layer(kRoom, "obstacles").c_str());
  ASSERT_TRUE(obstacles);
  ASSERT_TRUE(obstacles->GetSpatialRef());
  EXPECT_TRUE(obstacles->GetSpatialRef()->IsLocal());
  const long long id = map_id(kRoom);
  auto c = admin();
  size_t checked = 0;
  for (auto& f : *obstacles) {
    const long long ord = f->GetFieldAsInteger64("ord");
    mysqlpp::Query q = c->query("SELECT ax, ay, bx, `by` FROM segments WHERE map_id = " + std::to_string(id) +
                                " AND obstacle_ord = " + std::to_string(ord) + " ORDER BY ord");
    double twice_area = 0;
    for (const mysqlpp::Row& r : q.store())
      twice_area += std::stod(std::string(r[0])) * std::stod(std::string(r[3])) -
                    std::stod(std::string(r[2])) * std::stod(std::string(r[1]));
    const OGRPolygon* p = f->GetGeometryRef()->toPolygon();
    EXPECT_NEAR(p->get_Area(), std::abs(twice_area) / 2, 1e-9) << "obstacle ord " << ord;
    EXPECT_EQ(f->GetFID(), ord + 1);
    ++checked;
  }
  EXPECT_EQ(checked, static_cast<size_t>(summary(layer(kRoom, "obstacles")).count));
}

// A map in UTM (the frame is the CRS): ogrinfo reports EPSG:26910 and ogr2ogr keeps it.
TEST_F(GisLayersTest, UtmFrameIsReportedAsItsEpsgCrs) {
  Map m;
  m.border = {483000, 5457000, 483100, 5456900};
  Obstacle o;
  o.id = 1;
  o.type = ShapeType::ClosedPolygon;
  const std::vector<Point> ring = {{483010, 5456910}, {483010, 5456950}, {483060, 5456950}, {483060, 5456910}};
  for (size_t i = 0; i < ring.size(); ++i) {
    Segment seg;
    seg.a = ring[i];
    seg.b = ring[(i + 1) % ring.size()];
    seg.h = 3.0;
    o.segments.push_back(seg);
  }
  o.compute_bound();
  m.obstacles.push_back(o);
  auto c = connect_as(Role::Operator);
  MapStore store(*c);
  store.import(m, kUtm, "gis_layers_test", true);
  const MapGeoref g{"EPSG:26910", 0, 0, 0, 1};
  store.set_georef(kUtm, g);
  GisLayers(*c).publish(kUtm, map_frame_crs_wkt(kUtm, g));

  const LayerSummary s = summary(layer(kUtm, "segments"));
  ASSERT_TRUE(s.found);
  EXPECT_EQ(s.count, 4);
  auto crs = srs(s.srs_wkt);
  ASSERT_TRUE(crs->GetAuthorityCode(nullptr)) << s.srs_wkt;
  EXPECT_STREQ(crs->GetAuthorityName(nullptr), "EPSG");
  EXPECT_STREQ(crs->GetAuthorityCode(nullptr), "26910");
  EXPECT_NEAR(s.extent[0], 483010, 1e-6);
  EXPECT_NEAR(s.extent[3], 5456950, 1e-6);

  const std::string out = temp_path("gis-utm.gpkg");
  std::remove(out.c_str());
  int rc = 0;
  shell("ogr2ogr -f GPKG " + out + " " + connection() + " '" + layer(kUtm, "obstacles") + "'", &rc);
  ASSERT_EQ(rc, 0);
  std::unique_ptr<GDALDataset> ds(GDALDataset::Open(out.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY));
  ASSERT_TRUE(ds);
  const OGRSpatialReference* kept = ds->GetLayer(0)->GetSpatialRef();
  ASSERT_TRUE(kept);
  EXPECT_STREQ(kept->GetAuthorityCode(nullptr), "26910");
  EXPECT_EQ(ds->GetLayer(0)->GetFeatureCount(), 1);
}

// A rotated frame: the layers' CRS (and the GeoPackage's) puts map points where
// GeoTransform does (PROJ on the base CRS and the similarity), within 1e-9 degrees.
TEST_F(GisLayersTest, RotatedFrameIsADerivedCrsOnTheEarth) {
  RunResult r = run("fleetmap", "map georef " + kRoom + " 49.26 -123.25 --heading 0.5");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err.find("warning"), std::string::npos) << r.err;
  const GeoTransform t(georef_from_origin(49.26, -123.25, 0.5));
  const LayerSummary s = summary(layer(kRoom, "segments"));
  auto crs = srs(s.srs_wkt);
  for (const Point p : {Point{0, 0}, Point{15, 0}, Point{15, 15}, Point{-200, 700}}) {
    const std::array<double, 2> got = to_wgs84(*crs, p.x, p.y);
    const LonLat want = t.to_wgs84(p);
    EXPECT_NEAR(got[0], want.lon, 1e-9) << p.x << "," << p.y;
    EXPECT_NEAR(got[1], want.lat, 1e-9) << p.x << "," << p.y;
  }
  // The geometry stays in the map frame: the extent is the segments' own.
  const std::array<double, 4> seg = segment_extent(map_id(kRoom));
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(s.extent[i], seg[i], 1e-6);

  const std::string out = temp_path("gis-room-georef.gpkg");
  std::remove(out.c_str());
  int rc = 0;
  shell("ogr2ogr -f GPKG " + out + " " + connection() + " '" + layer(kRoom, "segments") + "'", &rc);
  ASSERT_EQ(rc, 0);
  std::unique_ptr<GDALDataset> ds(GDALDataset::Open(out.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY));
  ASSERT_TRUE(ds);
  const OGRSpatialReference* kept = ds->GetLayer(0)->GetSpatialRef();
  ASSERT_TRUE(kept);
  const std::array<double, 2> got = to_wgs84(*kept, 15, 15);
  EXPECT_NEAR(got[0], t.to_wgs84({15, 15}).lon, 1e-9);
  EXPECT_NEAR(got[1], t.to_wgs84({15, 15}).lat, 1e-9);

  r = run("fleetmap", "map georef " + kRoom + " --clear");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(srs(summary(layer(kRoom, "segments")).srs_wkt)->IsLocal());
}

// Robots' last positions in the map frame, GPS fixes in WGS 84 (x = lon); a robot
// account can read none of it.
TEST_F(GisLayersTest, RobotsAndGpsFixesAreLayersRobotsCannotRead) {
  const std::string password = add_robot("gisbot", kRoom);
  const long long rid = scalar("SELECT id FROM robots WHERE db_user = 'gisbot'");
  {
    auto c = admin();
    c->query("UPDATE robots SET x = 3.5, y = 4.25, theta = 0.5 WHERE id = " + std::to_string(rid)).execute();
    c->query("INSERT INTO gps_fixes (robot_id, t, lat, lon) VALUES (" + std::to_string(rid) +
             ", NOW(6), 49.2612345, -123.2456789)")
        .execute();
  }
  // The layers are a snapshot: 'gis publish' refreshes them, robots and GPS fixes included.
  RunResult r = run("fleetmap", "gis publish " + kRoom);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("published '" + kRoom + "'"), std::string::npos) << r.out;
  r = run("fleetmap", "gis list");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find(layer(kRoom, "robots") + "\tPOINT\t" +
                       std::to_string(GisLayers::map_srid(static_cast<unsigned>(map_id(kRoom))))),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("gps_fixes\tPOINT\t4326"), std::string::npos) << r.out;
  EXPECT_EQ(run("fleetmap", "gis publish no-such-map").exit_code, 4);

  const std::string robots = shell("ogrinfo -ro " + connection() + " '" + layer(kRoom, "robots") + "' -fid " +
                                   std::to_string(rid));
  EXPECT_NE(robots.find("name (String) = gisbot"), std::string::npos) << robots;
  EXPECT_NE(robots.find("POINT (3.5 4.25)"), std::string::npos) << robots;

  const LayerSummary gps = summary("gps_fixes");
  ASSERT_TRUE(gps.found);
  EXPECT_EQ(gps.count, scalar("SELECT COUNT(*) FROM gps_fixes"));
  auto crs = srs(gps.srs_wkt);
  EXPECT_STREQ(crs->GetAuthorityCode(nullptr), "4326");
  const long long fix = scalar("SELECT MAX(id) FROM gps_fixes WHERE robot_id = " + std::to_string(rid));
  const std::string one = shell("ogrinfo -ro " + connection() + " gps_fixes -fid " + std::to_string(fix));
  EXPECT_NE(one.find("POINT (-123.2456789 49.2612345)"), std::string::npos) << one;
  EXPECT_NE(one.find("robot (String) = gisbot"), std::string::npos) << one;

  SqlRobot robot("gisbot", password);
  const std::string gis_db = tcp_settings(Role::Inspector).database + "_gis";
  for (const std::string& t : {layer(kRoom, "robots"), std::string("gps_fixes"), std::string("geometry_columns")}) {
    mysqlpp::Query q = robot.connection().query("SELECT COUNT(*) FROM `" + gis_db + "`.`" + t + "`");
    EXPECT_THROW(q.store(), mysqlpp::BadQuery) << t;
  }
  // The inspector can.
  auto inspector = connect_as(Role::Inspector);
  mysqlpp::Query q = inspector->query("SELECT COUNT(*) FROM `" + gis_db + "`.`" + layer(kRoom, "robots") + "`");
  EXPECT_EQ(std::string(q.store()[0][0]), "1");
}

TEST_F(GisLayersTest, DeletedMapLeavesNoLayers) {
  const std::string name = "gis_doomed";
  RunResult r = run("fleetmap", "map import " + source_path("maps/example-room.map") + " --name " + name + " --replace");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  ASSERT_TRUE(summary(layer(name, "segments")).found);
  const long long id = map_id(name);
  r = run("fleetmap", "map delete " + name);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err.find("warning"), std::string::npos) << r.err;
  EXPECT_EQ(shell("ogrinfo -ro " + connection()).find(name + ":"), std::string::npos);
  const std::string gis_db = tcp_settings(Role::Inspector).database + "_gis";
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM `" + gis_db + "`.geometry_columns WHERE f_table_name LIKE '" + name + ":%'"), 0);
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM `" + gis_db + "`.spatial_ref_sys WHERE srid = " +
                   std::to_string(GisLayers::map_srid(static_cast<unsigned>(id)))),
            0);
}

}  // namespace
}  // namespace fleetmap::test
