// Exports for GIS tools, through the real program and database: every file read back by
// OGR (or GDAL) here and checked against the map it came from, coordinates against PROJ
// called directly on a Transverse Mercator written out in this file, and the real
// ogr2ogr reprojecting the GeoJSON.
#include <gdal_priv.h>
#include <ogrsf_frmts.h>
#include <proj.h>

#include <cmath>
#include <regex>
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "common/io/seed_format.h"
#include "protocol/connection.h"
#include "tests/integration/server_fixture.h"
#include "tests/integration/test_db.h"

namespace fleetmap::test {
namespace {

const std::string kRoom = "gx_room", kPlain = "gx_plain";
constexpr double kLat = 46.5191, kLon = 6.5668;

struct Closer {
  void operator()(GDALDataset* d) const { GDALClose(d); }
};
using Dataset = std::unique_ptr<GDALDataset, Closer>;

Dataset open_file(const std::string& path, unsigned flags = GDAL_OF_VECTOR) {
  GDALAllRegister();
  return Dataset(static_cast<GDALDataset*>(GDALOpenEx(path.c_str(), flags, nullptr, nullptr, nullptr)));
}

void import_room(const std::string& name) {
  RunResult r = run("fleetmap", "map import " + source_path("maps/example-room.map") + " --name " + name + " --replace");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = run("fleetmap", "objects import " + name + " " + source_path("maps/example-room.geojson") + " --replace");
  ASSERT_EQ(r.exit_code, 0) << r.err;
}

void georef(double heading) {
  RunResult r = run("fleetmap", "map georef " + kRoom + " " + std::to_string(kLat) + " " + std::to_string(kLon) +
                                    " --heading " + std::to_string(heading));
  ASSERT_EQ(r.exit_code, 0) << r.err;
}

// The local TM at the map origin, as PROJ reads it; the map x axis at `heading` in it.
std::string tm_at_origin() {
  return "+proj=tmerc +lat_0=" + std::to_string(kLat) + " +lon_0=" + std::to_string(kLon) +
         " +k=1 +x_0=0 +y_0=0 +ellps=WGS84 +units=m +no_defs +type=crs";
}

class Expected {
 public:
  explicit Expected(double heading) : c_(std::cos(heading)), s_(std::sin(heading)) {
    ctx_ = proj_context_create();
    PJ* raw = proj_create_crs_to_crs(ctx_, tm_at_origin().c_str(), "EPSG:4326", nullptr);
    pj_ = proj_normalize_for_visualization(ctx_, raw);
    proj_destroy(raw);
  }
  ~Expected() {
    proj_destroy(pj_);
    proj_context_destroy(ctx_);
  }
  Expected(const Expected&) = delete;
  Expected& operator=(const Expected&) = delete;
  // Map point -> (lon, lat).
  std::pair<double, double> operator()(Point m) const {
    const PJ_COORD c = proj_trans(pj_, PJ_FWD, proj_coord(c_ * m.x - s_ * m.y, s_ * m.x + c_ * m.y, 0, 0));
    return {c.xy.x, c.xy.y};
  }

 private:
  double c_, s_;
  PJ_CONTEXT* ctx_ = nullptr;
  PJ* pj_ = nullptr;
};

double ground_metres(double lon1, double lat1, std::pair<double, double> b) {
  const double k = 6378137.0 * M_PI / 180;
  return std::hypot((lon1 - b.first) * k * std::cos(lat1 * M_PI / 180), (lat1 - b.second) * k);
}

std::vector<Segment> segments_of(const Map& m) {
  std::vector<Segment> out;
  for (const Obstacle& o : m.obstacles) out.insert(out.end(), o.segments.begin(), o.segments.end());
  return out;
}

TEST(GisExport, GeoJsonOfAGeoreferencedMapIsWgs84) {
  import_room(kRoom);
  const double heading = 0.35;
  georef(heading);
  const std::string file = temp_path("gx_room.geojson");
  RunResult r = run("fleetmap", "map export " + kRoom + " --format geojson -o " + file);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  Dataset ds = open_file(file);
  ASSERT_TRUE(ds);
  OGRLayer* l = ds->GetLayer(0);
  const std::vector<Segment> segs = segments_of(read_seed_file(source_path("maps/example-room.map")));
  const Expected expected(heading);
  size_t n = 0;
  for (auto& f : *l) {
    if (std::string(f->GetFieldAsString("kind")) != "segment") continue;
    ASSERT_LT(n, segs.size());
    const OGRLineString* line = f->GetGeometryRef()->toLineString();
    EXPECT_LT(ground_metres(line->getX(0), line->getY(0), expected(segs[n].a)), 1e-3);
    EXPECT_LT(ground_metres(line->getX(1), line->getY(1), expected(segs[n].b)), 1e-3);
    ++n;
  }
  EXPECT_EQ(n, segs.size());
  // What failed with "Invalid latitude" when the file held map-frame metres.
  const std::string web = temp_path("gx_room_3857.geojson");
  std::remove(web.c_str());
  EXPECT_EQ(std::system(("ogr2ogr -f GeoJSON -t_srs EPSG:3857 " + web + " " + file + " 2>&1").c_str()), 0);
  Dataset back = open_file(web);
  ASSERT_TRUE(back);
  EXPECT_EQ(back->GetLayer(0)->GetFeatureCount(), static_cast<GIntBig>(segs.size() + 1));  // + the border

  // The map frame by arrangement, the seed file's coordinates as they are.
  r = run("fleetmap", "map export " + kRoom + " --format geojson --crs map");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j.at("fleetmap").at("frame"), "map");
  EXPECT_EQ(j.at("features")[1].at("geometry").at("coordinates")[0][0].get<double>(), segs[0].a.x);
  // The objects too: WGS 84 by default.
  r = run("fleetmap", "objects export " + kRoom);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out).at("fleetmap").at("frame"), "wgs84");
}

TEST(GisExport, GeoJsonOfAMapWithoutGeoreferenceNeedsCrsMap) {
  import_room(kPlain);
  RunResult r = run("fleetmap", "map export " + kPlain + " --format geojson");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--crs map"), std::string::npos) << r.err;
  EXPECT_EQ(run("fleetmap", "map export " + kPlain + " --format geojson --crs map").exit_code, 0);
  EXPECT_EQ(run("fleetmap", "map export " + kPlain + " --format gpkg --crs wgs84 -o " + temp_path("x.gpkg")).exit_code,
            2);
}

TEST(GisExport, GeoPackageCarriesTheMapsCrs) {
  import_room(kRoom);
  georef(0);  // the map frame is the TM at the origin itself
  const std::string file = temp_path("gx_room.gpkg");
  RunResult r = run("fleetmap", "map export " + kRoom + " --format gpkg -o " + file);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("objects 17"), std::string::npos) << r.err;
  Dataset ds = open_file(file);
  ASSERT_TRUE(ds);
  OGRSpatialReference tm;
  ASSERT_EQ(tm.SetFromUserInput(tm_at_origin().c_str()), OGRERR_NONE);
  tm.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  std::set<std::string> names;
  for (OGRLayer* l : ds->GetLayers()) {
    names.insert(l->GetName());
    ASSERT_NE(l->GetSpatialRef(), nullptr) << l->GetName();
    EXPECT_TRUE(l->GetSpatialRef()->IsSame(&tm)) << l->GetName();
    const OGRwkbGeometryType type = wkbFlatten(l->GetGeomType());
    std::set<GIntBig> fids;
    for (auto& f : *l) {
      EXPECT_TRUE(fids.insert(f->GetFID()).second);
      EXPECT_EQ(wkbFlatten(f->GetGeometryRef()->getGeometryType()), type);
      if (type == wkbPolygon || type == wkbMultiPolygon) {
        EXPECT_TRUE(f->GetGeometryRef()->IsValid()) << l->GetName() << " " << f->GetFID();
      }
    }
  }
  for (const char* n : {"border", "segments", "obstacles", "objects", "object_elements", "avoided_areas"})
    EXPECT_TRUE(names.count(n)) << n;
  // The real ogrinfo sees the layers with their CRS.
  r = RunResult{};
  FILE* p = popen(("ogrinfo -so -al " + file + " 2>&1").c_str(), "r");
  ASSERT_NE(p, nullptr);
  char buf[4096];
  size_t got = 0;
  while ((got = fread(buf, 1, sizeof buf, p)) > 0) r.out.append(buf, got);
  EXPECT_EQ(pclose(p), 0);
  EXPECT_NE(r.out.find("Layer name: segments"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("Transverse Mercator"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("FID Column = fid"), std::string::npos) << r.out;

  // A rotated frame: an engineering CRS in the map frame, or the base CRS transformed.
  georef(0.35);
  r = run("fleetmap", "map export " + kRoom + " --format gpkg --layer segments -o " + file);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  ds = open_file(file);
  ASSERT_TRUE(ds);
  ASSERT_EQ(ds->GetLayerCount(), 1);
  EXPECT_TRUE(ds->GetLayer(0)->GetSpatialRef()->IsLocal());
  r = run("fleetmap", "map export " + kRoom + " --format gpkg --crs base --layer segments -o " + file);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  ds = open_file(file);
  ASSERT_TRUE(ds);
  EXPECT_TRUE(ds->GetLayer(0)->GetSpatialRef()->IsSame(&tm));
}

TEST(GisExport, TrajectoryTimesAreIso8601Utc) {
  import_room(kRoom);
  georef(0.35);
  add_robot("gx_bot", kRoom);
  auto db = admin();
  const long long id = scalar("SELECT id FROM robots WHERE db_user = 'gx_bot'");
  execute(*db, "DELETE FROM trajectories WHERE robot_id = " + std::to_string(id));
  // Written by a session five hours east of UTC: the instant is 00:36:02.25 UTC.
  execute(*db, "SET time_zone = '+05:00'");
  execute(*db, "INSERT INTO trajectories (robot_id, t, x, y, theta, v, pos) VALUES (" + std::to_string(id) +
                   ", '2026-12-02 05:36:02.250000', 1, 2, 0.5, 0.25, Point(1, 2)), (" + std::to_string(id) +
                   ", '2026-12-02 05:36:03.000000', 2, 2, 0.5, 0.5, Point(2, 2))");
  RunResult r = run("fleetmap", "trajectory gx_bot --format geojson");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j.at("features").size(), 2u);
  const auto& p = j.at("features")[0].at("properties");
  const std::regex iso(R"(^\d{4}-\d{2}-\d{2}T\d{2}:\d{2}:\d{2}(\.\d+)?(Z|[+-]\d{2}:\d{2})$)");
  EXPECT_TRUE(std::regex_match(p.at("t").get<std::string>(), iso)) << p.at("t");
  EXPECT_EQ(p.at("t"), "2026-12-02T00:36:02.250000Z");
  EXPECT_EQ(p.at("theta"), 0.5);
  EXPECT_EQ(p.at("v"), 0.25);
  const Expected expected(0.35);
  const auto& c = j.at("features")[0].at("geometry").at("coordinates");
  EXPECT_LT(ground_metres(c[0], c[1], expected({1, 2})), 1e-3);

  const std::string file = temp_path("gx_track.gpkg");
  r = run("fleetmap", "map export " + kRoom + " --format gpkg --trajectories --layer trajectory_points -o " + file);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  Dataset ds = open_file(file);
  ASSERT_TRUE(ds);
  OGRLayer* l = ds->GetLayerByName("trajectory_points");
  ASSERT_NE(l, nullptr);
  EXPECT_EQ(l->GetFeatureCount(), 2);
  std::unique_ptr<OGRFeature> f(l->GetNextFeature());
  ASSERT_TRUE(f);
  int y, mo, d, h, mi, tz;
  float s;
  ASSERT_TRUE(f->GetFieldAsDateTime(f->GetFieldIndex("t"), &y, &mo, &d, &h, &mi, &s, &tz));
  EXPECT_EQ(h, 0);
  EXPECT_EQ(mi, 36);
  EXPECT_FLOAT_EQ(s, 2.25f);
  EXPECT_EQ(tz, 100);  // UTC
}

// The P5 raster after its header.
std::string pgm_pixels(const std::string& text) {
  std::istringstream in(text);
  std::string magic;
  int w = 0, h = 0, maxval = 0;
  in >> magic >> w >> h >> maxval;
  in.get();
  return text.substr(static_cast<size_t>(in.tellg()));
}

TEST(GisExport, Nav2PngHasThePgmsPixelsAndAWorldFile) {
  import_room(kRoom);
  const std::string pgm = temp_path("gx_nav2_pgm"), png = temp_path("gx_nav2_png");
  ASSERT_EQ(run("fleetmap", "map nav2 " + kRoom + " --laser-height 0.38 --resolution 0.1 -o " + pgm).exit_code, 0);
  RunResult r = run("fleetmap", "map nav2 " + kRoom + " --laser-height 0.38 --resolution 0.1 --image png -o " + png);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("bytes"), std::string::npos) << r.err;
  for (const std::string suffix : {"", "_keepout"}) {
    SCOPED_TRACE(suffix);
    const auto yaml = yaml_fields(read_file(png + suffix + ".yaml"));
    EXPECT_EQ(yaml.at("image"), "\"gx_nav2_png" + suffix + ".png\"");
    const std::string want = pgm_pixels(read_file(pgm + suffix + ".pgm"));
    Dataset ds = open_file(png + suffix + ".png", GDAL_OF_RASTER);
    ASSERT_TRUE(ds);
    const int w = ds->GetRasterXSize(), h = ds->GetRasterYSize();
    std::string got(static_cast<size_t>(w) * h, '\0');
    ASSERT_EQ(ds->GetRasterBand(1)->RasterIO(GF_Read, 0, 0, w, h, got.data(), w, h, GDT_Byte, 0, 0, nullptr), CE_None);
    EXPECT_EQ(got, want);
    // The world file (GDAL's reading of .pgw) against the YAML: resolution, and the
    // origin as the lower-left corner.
    double gt[6];
    ASSERT_EQ(ds->GetGeoTransform(gt), CE_None);
    const double res = std::stod(yaml.at("resolution"));
    double ox = 0, oy = 0;
    ASSERT_EQ(std::sscanf(yaml.at("origin").c_str(), "[%lf, %lf", &ox, &oy), 2);
    EXPECT_DOUBLE_EQ(gt[1], res);
    EXPECT_DOUBLE_EQ(gt[5], -res);
    EXPECT_NEAR(gt[0], ox, 1e-9);
    EXPECT_NEAR(gt[3] + h * gt[5], oy, 1e-9);
  }
}

}  // namespace
}  // namespace fleetmap::test
