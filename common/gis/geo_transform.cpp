#include "common/gis/geo_transform.h"

#include <proj.h>

#include <cmath>
#include <cstdio>

#include "common/core/error.h"

namespace fleetmap {

struct GeoTransform::Proj {
  std::mutex mutex;
  PJ_CONTEXT* ctx = nullptr;
  PJ* base = nullptr;      // the base CRS
  PJ* to_base = nullptr;   // WGS 84 lon/lat -> base (east, north), visualization order
  ~Proj() {
    proj_destroy(to_base);
    proj_destroy(base);
    proj_context_destroy(ctx);
  }
};

namespace {

std::string proj_error(PJ_CONTEXT* ctx) {
  const int e = proj_context_errno(ctx);
  return e ? proj_context_errno_string(ctx, e) : "unknown PROJ error";
}

// The base must be projected and in metres: the map frame is metric (seed 000).
void check_projected_metric(PJ_CONTEXT* ctx, PJ* crs, const std::string& def) {
  const PJ_TYPE t = proj_get_type(crs);
  if (t != PJ_TYPE_PROJECTED_CRS)
    throw BadInput("CRS '" + def + "': expected a projected CRS in metres, got " +
                   (proj_get_name(crs) ? std::string(proj_get_name(crs)) : std::string("another kind")));
  PJ* cs = proj_crs_get_coordinate_system(ctx, crs);
  double factor = 0;
  const char* unit = nullptr;
  const bool ok = cs && proj_cs_get_axis_info(ctx, cs, 0, nullptr, nullptr, nullptr, &factor, &unit, nullptr, nullptr);
  proj_destroy(cs);
  if (!ok || std::abs(factor - 1) > 1e-12)
    throw BadInput("CRS '" + def + "': expected metres, got " + (unit ? unit : "no unit"));
}

}  // namespace

GeoTransform::GeoTransform(const MapGeoref& g) : georef_(g), proj_(std::make_unique<Proj>()) {
  for (double d : {g.tx, g.ty, g.rotation, g.scale})
    if (!std::isfinite(d)) throw BadInput("georeference of CRS '" + g.crs + "': expected finite numbers");
  if (!(g.scale > 0)) throw BadInput("georeference of CRS '" + g.crs + "': expected scale > 0");
  proj_->ctx = proj_context_create();
  proj_log_level(proj_->ctx, PJ_LOG_NONE);  // errors reach the caller as BadInput, not stderr
  proj_->base = proj_create(proj_->ctx, g.crs.c_str());
  if (!proj_->base) throw BadInput("CRS '" + g.crs + "': " + proj_error(proj_->ctx));
  check_projected_metric(proj_->ctx, proj_->base, g.crs);
  PJ* raw = proj_create_crs_to_crs(proj_->ctx, "EPSG:4326", g.crs.c_str(), nullptr);
  if (!raw) throw BadInput("CRS '" + g.crs + "': no transformation from WGS 84: " + proj_error(proj_->ctx));
  proj_->to_base = proj_normalize_for_visualization(proj_->ctx, raw);
  proj_destroy(raw);
  if (!proj_->to_base) throw BadInput("CRS '" + g.crs + "': " + proj_error(proj_->ctx));
}

GeoTransform::~GeoTransform() = default;
GeoTransform::GeoTransform(GeoTransform&&) noexcept = default;
GeoTransform& GeoTransform::operator=(GeoTransform&&) noexcept = default;

Point GeoTransform::map_to_base(Point m) const {
  const double c = std::cos(georef_.rotation), s = std::sin(georef_.rotation), k = georef_.scale;
  return {georef_.tx + k * (c * m.x - s * m.y), georef_.ty + k * (s * m.x + c * m.y)};
}

Point GeoTransform::base_to_map(Point b) const {
  const double c = std::cos(georef_.rotation), s = std::sin(georef_.rotation), k = georef_.scale;
  const double dx = (b.x - georef_.tx) / k, dy = (b.y - georef_.ty) / k;
  return {c * dx + s * dy, -s * dx + c * dy};
}

namespace {

// One PROJ call; a point outside the CRS's domain comes back as HUGE_VAL or NaN.
PJ_COORD trans_or_throw(PJ* op, std::mutex& m, PJ_DIRECTION dir, double a, double b, const char* what,
                        const std::string& crs) {
  PJ_COORD out;
  {
    std::lock_guard lock(m);
    out = proj_trans(op, dir, proj_coord(a, b, 0, 0));
  }
  if (!std::isfinite(out.xy.x) || !std::isfinite(out.xy.y) || out.xy.x == HUGE_VAL) {
    char buf[96];
    std::snprintf(buf, sizeof buf, what, a, b);
    throw BadInput(buf + std::string(": outside the domain of CRS '") + crs + "'");
  }
  return out;
}

}  // namespace

Point GeoTransform::to_map(LonLat ll) const {
  const PJ_COORD out = trans_or_throw(proj_->to_base, proj_->mutex, PJ_FWD, ll.lon, ll.lat, "lon %.9g, lat %.9g",
                                      georef_.crs);
  return base_to_map({out.xy.x, out.xy.y});
}

LonLat GeoTransform::to_wgs84(Point m) const {
  const Point b = map_to_base(m);
  const PJ_COORD out = trans_or_throw(proj_->to_base, proj_->mutex, PJ_INV, b.x, b.y, "base (%.9g, %.9g)", georef_.crs);
  return {out.lp.lam, out.lp.phi};
}

std::string GeoTransform::base_wkt() const {
  std::lock_guard lock(proj_->mutex);
  const char* options[] = {"MULTILINE=NO", nullptr};
  const char* wkt = proj_as_wkt(proj_->ctx, proj_->base, PJ_WKT1_GDAL, options);
  if (!wkt) wkt = proj_as_wkt(proj_->ctx, proj_->base, PJ_WKT2_2019, options);
  return wkt ? wkt : "";
}

std::string local_tm_crs(double lat0, double lon0) {
  char b[160];
  std::snprintf(b, sizeof b, "+proj=tmerc +lat_0=%.17g +lon_0=%.17g +k=1 +x_0=0 +y_0=0 +ellps=WGS84 +units=m +type=crs",
                lat0, lon0);
  return b;
}

MapGeoref georef_from_origin(double lat0, double lon0, double heading) {
  MapGeoref g;
  g.crs = local_tm_crs(lat0, lon0);
  g.rotation = heading;
  return g;
}

}  // namespace fleetmap
