// A georeferenced map taken out of the database through its GIS layers by the real
// `ogr2ogr -f GPKG` (as the inspector, docs/gis-layers.md) and imported back with
// `fleetmap map import` as a second map gives the same segments within 1 mm, as directed
// segments (seed 000 section 3: the orientation is the map's meaning), and the same CRS.
// Segments come from SQL on both maps and are matched by brute force; the CRS is compared
// by PROJ (proj_is_equivalent_to) and by placing map points on the Earth with PROJ from
// each map's stored georeference, the similarity computed here, not by GeoTransform.
#include <gdal_priv.h>
#include <ogr_spatialref.h>
#include <ogrsf_frmts.h>
#include <proj.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/integration/test_db.h"

namespace fleetmap::test {
namespace {

std::string gis(const std::string& f) { return real_map("gis/" + f); }

// Runs a shell command (a GDAL tool); stdout and stderr go to files.
int shell(const std::string& cmd) {
  const int status = std::system((cmd + " >" + temp_path("rt-shell.out") + " 2>" + temp_path("rt-shell.err")).c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// The layers database as the inspector reaches it over TCP, as a GIS tool would.
std::string connection() {
  const DbSettings s = tcp_settings(Role::Inspector);
  return "'MYSQL:" + s.database + "_gis,host=" + s.host + ",port=" + std::to_string(s.port) + ",user=" + s.user +
         ",password=" + s.password + "'";
}

struct DirectedSegment {
  double ax, ay, bx, by, h;
};

std::vector<DirectedSegment> segments_of(const std::string& map) {
  auto c = admin();
  mysqlpp::Query q = c->query();
  q << "SELECT s.ax, s.ay, s.bx, s.`by`, s.h FROM segments s JOIN maps m ON m.id = s.map_id WHERE m.name = "
    << mysqlpp::quote << map;
  std::vector<DirectedSegment> out;
  for (const mysqlpp::Row& r : q.store())
    out.push_back({std::stod(std::string(r[0])), std::stod(std::string(r[1])), std::stod(std::string(r[2])),
                   std::stod(std::string(r[3])), std::stod(std::string(r[4]))});
  return out;
}

struct Matching {
  size_t unmatched = 0;
  double worst = 0;  // the largest endpoint distance of a matched pair (m)
};

// Brute force: every segment of a takes the first unused segment of b whose start is
// within tol of its start, whose end is within tol of its end, and whose height agrees.
Matching match(const std::vector<DirectedSegment>& a, const std::vector<DirectedSegment>& b, double tol) {
  Matching m;
  std::vector<bool> used(b.size(), false);
  for (const DirectedSegment& s : a) {
    bool found = false;
    for (size_t j = 0; j < b.size() && !found; ++j) {
      if (used[j]) continue;
      const double da = std::hypot(s.ax - b[j].ax, s.ay - b[j].ay), db = std::hypot(s.bx - b[j].bx, s.by - b[j].by);
      if (da <= tol && db <= tol && std::abs(s.h - b[j].h) <= tol) {
        used[j] = found = true;
        m.worst = std::max({m.worst, da, db});
      }
    }
    if (!found) ++m.unmatched;
  }
  return m;
}

struct StoredGeoref {
  std::string crs;
  double tx = 0, ty = 0, rotation = 0, scale = 1;
};

StoredGeoref georef_of(const std::string& map) {
  auto c = admin();
  mysqlpp::Query q = c->query();
  q << "SELECT geo_crs, geo_tx, geo_ty, geo_rotation, geo_scale FROM maps WHERE geo_crs IS NOT NULL AND name = "
    << mysqlpp::quote << map;
  const mysqlpp::StoreQueryResult r = q.store();
  if (r.empty()) return {};
  return {std::string(r[0][0]), std::stod(std::string(r[0][1])), std::stod(std::string(r[0][2])),
          std::stod(std::string(r[0][3])), std::stod(std::string(r[0][4]))};
}

// A map point on the Earth from a stored georeference: base = t + k R(theta) p (map_georef.h),
// then PROJ from the base CRS to WGS 84 (lon, lat in degrees).
std::array<double, 2> on_earth(const StoredGeoref& g, double x, double y) {
  PJ_CONTEXT* ctx = proj_context_create();
  PJ* raw = proj_create_crs_to_crs(ctx, g.crs.c_str(), "EPSG:4326", nullptr);
  EXPECT_TRUE(raw) << g.crs;
  if (!raw) {
    proj_context_destroy(ctx);
    return {NAN, NAN};
  }
  PJ* t = proj_normalize_for_visualization(ctx, raw);
  const double c = std::cos(g.rotation), s = std::sin(g.rotation);
  const PJ_COORD base = proj_coord(g.tx + g.scale * (c * x - s * y), g.ty + g.scale * (s * x + c * y), 0, 0);
  const PJ_COORD ll = proj_trans(t, PJ_FWD, base);
  proj_destroy(t);
  proj_destroy(raw);
  proj_context_destroy(ctx);
  return {ll.xy.x, ll.xy.y};
}

bool proj_equivalent(const std::string& a, const std::string& b) {
  PJ_CONTEXT* ctx = proj_context_create();
  PJ* pa = proj_create(ctx, a.c_str());
  PJ* pb = proj_create(ctx, b.c_str());
  const bool same = pa && pb && proj_is_equivalent_to(pa, pb, PJ_COMP_EQUIVALENT);
  proj_destroy(pa);
  proj_destroy(pb);
  proj_context_destroy(ctx);
  return same;
}

// The CRS of a GeoPackage layer as OGR reads it, in WKT2 (a derived CRS has no WKT1).
std::string layer_crs(const std::string& gpkg, const std::string& layer) {
  std::unique_ptr<GDALDataset> ds(GDALDataset::Open(gpkg.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY));
  EXPECT_TRUE(ds) << gpkg;
  if (!ds) return "";
  OGRLayer* l = ds->GetLayerByName(layer.c_str());
  EXPECT_TRUE(l && l->GetSpatialRef()) << layer;
  if (!l || !l->GetSpatialRef()) return "";
  char* wkt = nullptr;
  const char* const options[] = {"FORMAT=WKT2_2019", nullptr};
  l->GetSpatialRef()->exportToWkt(&wkt, options);
  std::string s = wkt ? wkt : "";
  CPLFree(wkt);
  return s;
}

// Heights come back through the layers' h_max (one height per obstacle in these maps).
const char* const kBackRules = R"({"rules": [
  {"geometry": "polygon", "action": "closed", "height": {"attribute": "h_max"}},
  {"geometry": "line", "action": "open", "height": {"attribute": "h_max"}}]})";

// map -> GeoPackage (ogr2ogr from the GIS layers) -> map `back`; the GeoPackage's path.
std::string round_trip(const std::string& map, const std::string& back) {
  const std::string gpkg = temp_path(map + ".gpkg");
  std::remove(gpkg.c_str());
  const int rc = shell("ogr2ogr -f GPKG " + gpkg + " " + connection() + " '" + map + ":obstacles' '" + map +
                       ":open_obstacles'");
  EXPECT_EQ(rc, 0) << read_file(temp_path("rt-shell.err"));
  const std::string rules = temp_path("rt-back-rules.json");
  write_file(rules, kBackRules);
  const RunResult r = run("fleetmap", "map import " + gpkg + " --rules " + rules + " --name " + back + " --replace");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err.find("warning"), std::string::npos) << r.err;
  return gpkg;
}

void expect_same_segments(const std::string& map, const std::string& back) {
  const std::vector<DirectedSegment> a = segments_of(map), b = segments_of(back);
  ASSERT_GT(a.size(), 50u);
  EXPECT_EQ(a.size(), b.size());
  const Matching ab = match(a, b, 1e-3), ba = match(b, a, 1e-3);
  EXPECT_EQ(ab.unmatched, 0u) << "of " << a.size();
  EXPECT_EQ(ba.unmatched, 0u) << "of " << b.size();
  EXPECT_LE(ab.worst, 1e-3);
  // The orientation is checked: reversed, only the segments whose twin runs the other
  // way in the same map match (walls between two rooms of the DXF), and most do not.
  const auto reversed = [](std::vector<DirectedSegment> v) {
    for (DirectedSegment& s : v) s = {s.bx, s.by, s.ax, s.ay, s.h};
    return v;
  };
  const size_t lone = match(a, reversed(a), 1e-3).unmatched;
  EXPECT_GT(lone, a.size() / 2);
  EXPECT_EQ(match(a, reversed(b), 1e-3).unmatched, lone);
}

class GisRoundTrip : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { GDALAllRegister(); }
};

// UBC buildings in UTM (EPSG:26910): the frame is the CRS, polygons through `obstacles`.
TEST_F(GisRoundTrip, UtmMapThroughGpkgGivesTheSameSegmentsAndCrs) {
  const std::string rules = temp_path("rt-ubc-rules.json");
  write_file(rules, R"({"rules": [{"key": "BLDG_ID", "action": "closed", "values":
    ["ACEN", "ALRD", "ALUM", "AMBS"]}]})");
  const RunResult r = run("fleetmap", "map import " + gis("ubc-vancouver/buildings-2019/ubcv_buildings_gpkg.gpkg") +
                                          " --layer ubcv_buildings --rules " + rules + " --name rt_ubc --replace");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string gpkg = round_trip("rt_ubc", "rt_ubc_back");
  expect_same_segments("rt_ubc", "rt_ubc_back");

  const StoredGeoref a = georef_of("rt_ubc"), b = georef_of("rt_ubc_back");
  EXPECT_EQ(a.crs, "EPSG:26910");
  EXPECT_EQ(b.crs, "EPSG:26910");
  EXPECT_TRUE(proj_equivalent(layer_crs(gpkg, "rt_ubc:obstacles"), "EPSG:26910"));
  EXPECT_EQ(b.tx, 0);
  EXPECT_EQ(b.rotation, 0);
  EXPECT_EQ(b.scale, 1);
}

// The DXF floor georeferenced by its three control points (rotated, scaled, offset from
// a local TM): a derived CRS in the GeoPackage; lines through `open_obstacles`.
TEST_F(GisRoundTrip, ControlPointFrameThroughGpkgGivesTheSameSegmentsAndCrs) {
  setenv("DXF_ENCODING", "UTF-8", 1);  // the file's code page lies (gis/README.md)
  RunResult r = run("fleetmap", "map import " + gis("dxf-openindoor-clermont/plan.dxf") + " --name rt_floor --replace");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // The README's control points, DXF cm as map metres.
  r = run("fleetmap",
          "map georef rt_floor --control 107.627211865239,47.3217310712035,45.75836725,3.11171115"
          " --control 212.16987615174,46.931816899378,45.75924865,3.11118275"
          " --control 238.268469081387,126.045563252596,45.7591626,3.11011255");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string gpkg = round_trip("rt_floor", "rt_floor_back");
  expect_same_segments("rt_floor", "rt_floor_back");

  const StoredGeoref a = georef_of("rt_floor"), b = georef_of("rt_floor_back");
  ASSERT_FALSE(a.crs.empty());
  ASSERT_FALSE(b.crs.empty());
  EXPECT_GT(std::abs(a.rotation), 0.1);  // a frame that is not its base CRS
  // The GeoPackage holds a derived CRS; the map read back from it has the original's
  // base CRS and similarity.
  EXPECT_EQ(layer_crs(gpkg, "rt_floor:open_obstacles").rfind("DERIVEDPROJCRS[", 0), 0u);
  EXPECT_TRUE(proj_equivalent(a.crs, b.crs)) << a.crs << "\n" << b.crs;
  EXPECT_NEAR(b.tx, a.tx, 1e-6);
  EXPECT_NEAR(b.ty, a.ty, 1e-6);
  EXPECT_NEAR(b.rotation, a.rotation, 1e-12);
  EXPECT_NEAR(b.scale, a.scale, 1e-12);
  // The same places on the Earth, each from its own stored georeference (1e-9 deg ~ 0.1 mm).
  for (const auto& [x, y] : {std::array<double, 2>{107.6, 47.3}, {238.3, 126.0}, {0, 0}, {1000, -500}}) {
    const std::array<double, 2> p = on_earth(a, x, y), q = on_earth(b, x, y);
    EXPECT_NEAR(p[0], q[0], 1e-9) << x << "," << y;
    EXPECT_NEAR(p[1], q[1], 1e-9) << x << "," << y;
  }
}

}  // namespace
}  // namespace fleetmap::test
