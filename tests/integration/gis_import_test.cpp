// map import of GIS sources (common/gis/ogr_import.h) through the real `fleetmap` and a
// real MariaDB: what is stored, the georeference, the objects, all or nothing. The
// geometry itself is checked against OGR in tests/common/gis/ogr_import_test.cpp.
#include <gtest/gtest.h>

#include <cstdlib>

#include "tests/integration/test_db.h"

namespace fleetmap::test {
namespace {

std::string gis(const std::string& f) { return real_map("gis/" + f); }

long long map_count(const std::string& name) { return scalar("SELECT COUNT(*) FROM maps WHERE name = '" + name + "'"); }

long long count_of(const std::string& table, const std::string& name) {
  return scalar("SELECT COUNT(*) FROM " + table + " t JOIN maps m ON m.id = t.map_id WHERE m.name = '" + name + "'");
}

// The number after `what` in the importer's "total: ..." line.
long long reported(const std::string& out, const std::string& what) {
  const size_t t = out.find("total: ");
  const size_t w = out.find(what, t);
  if (t == std::string::npos || w == std::string::npos) return -1;
  const size_t start = out.rfind(' ', w - 2);
  return std::atoll(out.substr(start + 1, w - start - 1).c_str());
}

std::string georef_crs(const std::string& name) {
  auto c = admin();
  mysqlpp::Query q = c->query("SELECT COALESCE(geo_crs, '') FROM maps WHERE name = " + std::string("'") + name + "'");
  mysqlpp::StoreQueryResult r = q.store();
  return r.empty() ? "" : std::string(r[0][0]);
}

TEST(GisImport, OsmCampusStoresObstaclesObjectsAndItsFrame) {
  RunResult r = run("fleetmap", "map import " + gis("osm-montgomery-college-rockville/campus.osm") +
                                    " --name it_gis_campus --replace");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("layer multipolygons: 131 read"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("extent (WGS 84): lon -77.16"), std::string::npos) << r.out;
  EXPECT_EQ(count_of("segments", "it_gis_campus"), reported(r.out, "segments"));
  EXPECT_EQ(count_of("obstacles", "it_gis_campus"), reported(r.out, "obstacles"));
  EXPECT_GT(count_of("env_objects", "it_gis_campus"), 0);
  EXPECT_EQ(count_of("env_objects", "it_gis_campus"), reported(r.out, "objects"));
  EXPECT_EQ(georef_crs("it_gis_campus").rfind("+proj=tmerc", 0), 0u) << georef_crs("it_gis_campus");
  // Stairs (ST 5) from highway=steps, buildings with their heights from the tags.
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM obstacles o JOIN maps m ON m.id = o.map_id WHERE m.name = 'it_gis_campus'"
                   " AND o.st = 5"),
            13);
}

TEST(GisImport, GeoJsonIntoTheFrameOfAUtmMapAgrees) {
  // Ten buildings only, chosen by a rules file: the whole campus takes seconds to store.
  const std::string rules = temp_path("ubc_rules.json");
  write_file(rules, R"({"rules": [{"key": "BLDG_ID", "action": "closed", "values":
    ["ACAH", "ACAP", "ACDY", "ACEN", "ACOM", "ACU", "AERL", "ALRD", "ALUM", "AMBS"]}]})");
  RunResult a = run("fleetmap", "map import " + gis("ubc-vancouver/buildings-2019/ubcv_buildings_gpkg.gpkg") +
                                    " --layer ubcv_buildings --rules " + rules + " --name it_gis_ubc_utm --replace");
  ASSERT_EQ(a.exit_code, 0) << a.err;
  EXPECT_EQ(georef_crs("it_gis_ubc_utm"), "EPSG:26910");
  RunResult b = run("fleetmap", "map import " + gis("ubc-vancouver/buildings-2019/ubcv_buildings.geojson") +
                                    " --rules " + rules + " --frame-of it_gis_ubc_utm --name it_gis_ubc_wgs --replace");
  ASSERT_EQ(b.exit_code, 0) << b.err;
  EXPECT_NE(b.out.find("10 kept"), std::string::npos) << b.out;
  EXPECT_NE(b.out.find("skipped 260: no rule"), std::string::npos) << b.out;
  EXPECT_EQ(georef_crs("it_gis_ubc_wgs"), "EPSG:26910");
  // The same buildings: extents within a few centimetres (README: 1.4 cm worst).
  for (const char* f : {"MIN(s.ax)", "MAX(s.ax)", "MIN(s.ay)", "MAX(s.ay)"}) {
    auto c = admin();
    auto q = c->query(std::string("SELECT ") + f + " FROM segments s JOIN maps m ON m.id = s.map_id WHERE m.name = " +
                      "'it_gis_ubc_utm' UNION ALL SELECT " + f +
                      " FROM segments s JOIN maps m ON m.id = s.map_id WHERE m.name = 'it_gis_ubc_wgs'");
    auto res = q.store();
    ASSERT_EQ(res.num_rows(), 2u);
    EXPECT_NEAR(double(res[0][0]), double(res[1][0]), 0.03) << f;
  }
}

TEST(GisImport, DxfInCentimetresHasNoGeoreference) {
  setenv("DXF_ENCODING", "UTF-8", 1);
  RunResult r = run("fleetmap", "map import " + gis("dxf-openindoor-clermont/plan.dxf") + " --name it_gis_dxf --replace");
  unsetenv("DXF_ENCODING");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("0.010000 m per unit"), std::string::npos) << r.out;
  EXPECT_EQ(georef_crs("it_gis_dxf"), "");
  // README bbox in cm, stored in metres
  EXPECT_NEAR(static_cast<double>(scalar("SELECT ROUND(MAX(s.bx) * 1000) FROM segments s JOIN maps m ON "
                                         "m.id = s.map_id WHERE m.name = 'it_gis_dxf'")) / 1000,
              239.9057, 0.01);
}

TEST(GisImport, MalformedOrInvalidSourceImportsNothing) {
  const std::string truncated = temp_path("truncated.geojson");
  write_file(truncated, R"({"type": "FeatureCollection", "features": [{"type": "Feature", "properties": {"n)");
  RunResult t = run("fleetmap", "map import " + truncated + " --name it_gis_bad");
  EXPECT_EQ(t.exit_code, 2) << t.err;
  EXPECT_NE(t.err.find(truncated), std::string::npos) << t.err;
  EXPECT_EQ(map_count("it_gis_bad"), 0);

  const std::string bowtie = temp_path("bowtie.geojson");
  write_file(bowtie, R"({"type": "FeatureCollection", "features": [
    {"type": "Feature", "id": 1, "properties": {"long": ")" + std::string(2000, 'x') + R"("},
     "geometry": {"type": "Polygon",
     "coordinates": [[[0, 0], [10, 0], [10, 10], [0, 10], [0, 0]]]}},
    {"type": "Feature", "id": 7, "properties": {}, "geometry": {"type": "Polygon",
     "coordinates": [[[20, 0], [30, 10], [30, 0], [20, 10], [20, 0]]]}}]})");
  RunResult v = run("fleetmap", "map import " + bowtie + " --crs EPSG:32631 --invalid refuse --name it_gis_bad");
  EXPECT_EQ(v.exit_code, 2) << v.err;
  EXPECT_NE(v.err.find("feature 7"), std::string::npos) << v.err;
  EXPECT_EQ(map_count("it_gis_bad"), 0);
  // Repaired by default, and said so.
  RunResult ok = run("fleetmap", "map import " + bowtie + " --crs EPSG:32631 --name it_gis_bowtie --replace");
  EXPECT_EQ(ok.exit_code, 0) << ok.err;
  EXPECT_NE(ok.err.find("feature 7"), std::string::npos) << ok.err;
  EXPECT_EQ(count_of("obstacles", "it_gis_bowtie"), 3);
  // Every attribute kept: obstacles.semantic is TEXT.
  EXPECT_GT(scalar("SELECT MAX(LENGTH(o.semantic)) FROM obstacles o JOIN maps m ON m.id = o.map_id WHERE m.name = "
                   "'it_gis_bowtie'"),
            2000);
}

}  // namespace
}  // namespace fleetmap::test
