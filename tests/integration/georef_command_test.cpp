// `fleetmap map georef` end to end on the test database: a control-point fit with the
// DXF floor plan's ground control points (../shared/maps/gis/README.md), read back by
// the CLI, the views and the inspector, then SendGPS through the real server stores the
// map position that PROJ itself gives for the stored georeference.
#include <geodesic.h>
#include <proj.h>

#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "protocol/connection.h"
#include "tests/integration/server_fixture.h"
#include "tests/integration/test_db.h"

namespace fleetmap::test {
namespace {

// The README's points (DXF cm) in map metres: a map imported from that DXF is cm / 100.
const char* const kControls =
    " --control 107.627211865239,47.3217310712035,45.75836725,3.11171115"
    " --control 212.16987615174,46.931816899378,45.75924865,3.11118275"
    " --control 238.268469081387,126.045563252596,45.7591626,3.11011255";
const double kFix[3][2] = {{45.75836725, 3.11171115}, {45.75924865, 3.11118275}, {45.7591626, 3.11011255}};
const double kMap[3][2] = {{107.627211865239, 47.3217310712035}, {212.16987615174, 46.931816899378},
                           {238.268469081387, 126.045563252596}};

std::string text(const std::string& sql) {
  auto c = admin();
  mysqlpp::Query q = c->query(sql);
  const auto r = q.store();
  return r.empty() || r[0][0].is_null() ? std::string("NULL") : std::string(r[0][0]);
}

double number(const std::string& sql) { return std::stod(text(sql)); }

// The stored georeference computed with PROJ's C API directly: WGS 84 -> base CRS, then
// the similarity base = t + k R(rot) map undone by hand (sql/10_schema.sql's definition).
struct StoredGeoref {
  std::string crs;
  double tx, ty, rot, k;
  explicit StoredGeoref(const std::string& map) {
    const std::string w = " FROM maps WHERE name = '" + map + "'";
    crs = text("SELECT geo_crs" + w);
    tx = number("SELECT geo_tx" + w);
    ty = number("SELECT geo_ty" + w);
    rot = number("SELECT geo_rotation" + w);
    k = number("SELECT geo_scale" + w);
  }
  PJ* op(PJ_CONTEXT* ctx) const {
    PJ* raw = proj_create_crs_to_crs(ctx, "EPSG:4326", crs.c_str(), nullptr);
    PJ* norm = proj_normalize_for_visualization(ctx, raw);
    proj_destroy(raw);
    return norm;
  }
  void to_map(double lat, double lon, double& x, double& y) const {
    PJ_CONTEXT* ctx = proj_context_create();
    PJ* p = op(ctx);
    const PJ_COORD b = proj_trans(p, PJ_FWD, proj_coord(lon, lat, 0, 0));
    proj_destroy(p);
    proj_context_destroy(ctx);
    const double dx = (b.xy.x - tx) / k, dy = (b.xy.y - ty) / k;
    x = std::cos(rot) * dx + std::sin(rot) * dy;
    y = -std::sin(rot) * dx + std::cos(rot) * dy;
  }
  void to_wgs84(double x, double y, double& lat, double& lon) const {
    PJ_CONTEXT* ctx = proj_context_create();
    PJ* p = op(ctx);
    const double bx = tx + k * (std::cos(rot) * x - std::sin(rot) * y);
    const double by = ty + k * (std::sin(rot) * x + std::cos(rot) * y);
    const PJ_COORD ll = proj_trans(p, PJ_INV, proj_coord(bx, by, 0, 0));
    proj_destroy(p);
    proj_context_destroy(ctx);
    lon = ll.lp.lam;
    lat = ll.lp.phi;
  }
};

double geodesic_distance(double lat1, double lon1, double lat2, double lon2) {
  geod_geodesic g;
  geod_init(&g, 6378137, 1 / 298.257223563);
  double s = 0;
  geod_inverse(&g, lat1, lon1, lat2, lon2, &s, nullptr, nullptr);
  return s;
}

TEST(GeorefCommand, ControlPointFitIsStoredPrintedAndUsedBySendGps) {
  ensure_example_map("georef_map");
  ASSERT_EQ(run("fleetmap", "map georef georef_map --clear").exit_code, 0);
  RunResult r = run("fleetmap", "map georef georef_map");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("not georeferenced"), std::string::npos) << r.out;

  r = run("fleetmap", std::string("map georef georef_map") + kControls);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* want : {"control point 1:", "control point 3:", "rms ", "scale "})
    EXPECT_NE(r.out.find(want), std::string::npos) << want << " in\n" << r.out;

  // Stored: the local TM, three points whose residuals PROJ and the geodesic confirm.
  const StoredGeoref g("georef_map");
  EXPECT_EQ(g.crs.rfind("+proj=tmerc", 0), 0u) << g.crs;
  EXPECT_NEAR(g.k, 1, 0.01);
  const std::string mid = std::to_string(scalar("SELECT id FROM maps WHERE name = 'georef_map'"));
  ASSERT_EQ(scalar("SELECT COUNT(*) FROM georef_control_points WHERE map_id = " + mid), 3);
  double sq = 0;
  for (int i = 0; i < 3; ++i) {
    const std::string w = " FROM georef_control_points WHERE map_id = " + mid + " AND ord = " + std::to_string(i + 1);
    EXPECT_DOUBLE_EQ(number("SELECT lat" + w), kFix[i][0]);
    EXPECT_DOUBLE_EQ(number("SELECT x" + w), kMap[i][0]);
    double lat = 0, lon = 0;
    g.to_wgs84(kMap[i][0], kMap[i][1], lat, lon);
    const double d = geodesic_distance(lat, lon, kFix[i][0], kFix[i][1]);
    EXPECT_NEAR(number("SELECT residual_m" + w), d, 1e-6) << "point " << i + 1;
    sq += d * d;
  }
  // The three points are no exact similarity of each other: about a metre is the data's
  // (docs/georeference.md).
  EXPECT_LT(std::sqrt(sq / 3), 1.0);

  // Read back by the CLI and by the inspector's views.
  r = run("fleetmap", "map georef georef_map");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* want : {"base CRS:", "+proj=tmerc", "rotation:", "scale:", "map origin (0, 0): lat 45.7",
                           "border corners:", "control points: 3, rms"})
    EXPECT_NE(r.out.find(want), std::string::npos) << want << " in\n" << r.out;
  auto inspector = connect(tcp_settings(Role::Inspector));
  mysqlpp::Query q = inspector->query("SELECT geo_crs FROM v_maps WHERE name = 'georef_map'");
  EXPECT_EQ(std::string(q.store()[0][0]), g.crs);
  q = inspector->query("SELECT COUNT(*) FROM v_georef_control_points WHERE map = 'georef_map'");
  EXPECT_EQ(std::string(q.store()[0][0]), "3");

  // SendGPS 30 m north-east of point 2 stores the map position PROJ gives.
  geod_geodesic geod;
  geod_init(&geod, 6378137, 1 / 298.257223563);
  double lat = 0, lon = 0;
  geod_direct(&geod, kFix[1][0], kFix[1][1], 45, 30, &lat, &lon, nullptr);
  double x = 0, y = 0;
  g.to_map(lat, lon, x, y);
  const std::string pw = add_robot("georef_r1", "georef_map");
  const long long robot = scalar("SELECT id FROM robots WHERE db_user = 'georef_r1'");
  {
    ServerProcess server("", "georef_server.log");
    SqlRobot bot("georef_r1", pw);
    bot.send("Ready", R"({"magic": 1})");
    ASSERT_EQ(bot.receive(2).size(), 2u);
    char params[128];
    std::snprintf(params, sizeof params, R"({"lat": %.12f, "lon": %.12f})", lat, lon);
    bot.send("SendGPS", params);
    ASSERT_EQ(bot.receive(1).size(), 1u);
  }
  const std::string last = " FROM gps_fixes WHERE robot_id = " + std::to_string(robot) + " ORDER BY id DESC LIMIT 1";
  EXPECT_NEAR(number("SELECT x" + last), x, 1e-4);
  EXPECT_NEAR(number("SELECT y" + last), y, 1e-4);
  // And that is 30 ground metres from where point 2's fix lands: 30 / scale map metres.
  double x2 = 0, y2 = 0;
  g.to_map(kFix[1][0], kFix[1][1], x2, y2);
  EXPECT_NEAR(std::hypot(x - x2, y - y2), 30 / g.k, 1e-3);

  // --clear removes the georeference and its points.
  ASSERT_EQ(run("fleetmap", "map georef georef_map --clear").exit_code, 0);
  EXPECT_EQ(text("SELECT geo_crs FROM maps WHERE id = " + mid), "NULL");
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM georef_control_points WHERE map_id = " + mid), 0);
}

TEST(GeorefCommand, RefusesAScaleFarFromOneAndBadInput) {
  ensure_example_map("georef_map");
  ASSERT_EQ(run("fleetmap", "map georef georef_map --clear").exit_code, 0);
  // The same points in centimetres: scale 0.01, refused, nothing stored.
  RunResult r = run("fleetmap",
                    "map georef georef_map --control 10762.7211865239,4732.17310712035,45.75836725,3.11171115"
                    " --control 21216.987615174,4693.1816899378,45.75924865,3.11118275");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--allow-scale"), std::string::npos) << r.err;
  EXPECT_EQ(text("SELECT geo_crs FROM maps WHERE name = 'georef_map'"), "NULL");
  // One point, a malformed one, an unknown map, a CRS in degrees, conflicting modes.
  EXPECT_EQ(run("fleetmap", "map georef georef_map --control 1,2,45,3").exit_code, 2);
  r = run("fleetmap", "map georef georef_map --control 1,2,45,3 --control 5,2,45.1");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--control 2: expected x,y,lat,lon"), std::string::npos) << r.err;
  EXPECT_EQ(run("fleetmap", "map georef no_such_map").exit_code, 4);
  EXPECT_EQ(run("fleetmap", "map georef no_such_map --control 1,2,45,3 --control 5,2,45.1,3").exit_code, 4);
  EXPECT_EQ(run("fleetmap", "map georef georef_map --crs EPSG:4326").exit_code, 2);
  EXPECT_EQ(run("fleetmap", "map georef georef_map 45 3 --clear").exit_code, 64);
  EXPECT_EQ(text("SELECT geo_crs FROM maps WHERE name = 'georef_map'"), "NULL");
}

TEST(GeorefCommand, CrsWithOffsetAndRotation) {
  ensure_example_map("georef_map");
  // A fit first: setting the CRS afterwards drops its control points.
  ASSERT_EQ(run("fleetmap", std::string("map georef georef_map") + kControls).exit_code, 0);
  const std::string points = "SELECT COUNT(*) FROM v_georef_control_points WHERE map = 'georef_map'";
  ASSERT_EQ(scalar(points), 3);
  RunResult r = run("fleetmap", "map georef georef_map --crs EPSG:26910 --offset 481000.5,5456000.25 --rotation 0.1");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(scalar(points), 0);
  const StoredGeoref g("georef_map");
  EXPECT_EQ(g.crs, "EPSG:26910");
  EXPECT_EQ(g.tx, 481000.5);
  EXPECT_EQ(g.ty, 5456000.25);
  EXPECT_EQ(g.rot, 0.1);
  EXPECT_EQ(g.k, 1);
  r = run("fleetmap", "map georef georef_map");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("NAD83 / UTM zone 10N"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("control points"), std::string::npos) << r.out;
  // The map origin printed is where PROJ puts the offset.
  double lat = 0, lon = 0;
  g.to_wgs84(0, 0, lat, lon);
  char want[64];
  std::snprintf(want, sizeof want, "lat %.9f, lon %.9f", lat, lon);
  EXPECT_NE(r.out.find(want), std::string::npos) << want << " in\n" << r.out;
  ASSERT_EQ(run("fleetmap", "map georef georef_map --clear").exit_code, 0);
}

}  // namespace
}  // namespace fleetmap::test
