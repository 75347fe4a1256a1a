#include "common/gis/map_frame_crs.h"

#include <proj.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <memory>

#include "common/core/error.h"
#include "common/gis/geo_transform.h"

namespace fleetmap {

namespace {

// WKT strings quote with '"', doubled inside a name.
std::string wkt_name(const std::string& s) {
  std::string out;
  for (char ch : s) {
    out += ch;
    if (ch == '"') out += '"';
  }
  return out;
}

std::string num(double v) {
  char b[40];
  std::snprintf(b, sizeof b, "%.17g", v);
  return b;
}

// The base CRS as WKT2:2019 PROJCRS[...], one line: WKT1 cannot hold a derived CRS.
std::string base_wkt2(const std::string& def) {
  using Ctx = std::unique_ptr<PJ_CONTEXT, decltype(&proj_context_destroy)>;
  using Obj = std::unique_ptr<PJ, decltype(&proj_destroy)>;
  Ctx ctx(proj_context_create(), proj_context_destroy);
  proj_log_level(ctx.get(), PJ_LOG_NONE);
  Obj crs(proj_create(ctx.get(), def.c_str()), proj_destroy);
  const char* options[] = {"MULTILINE=NO", nullptr};
  const char* wkt = crs ? proj_as_wkt(ctx.get(), crs.get(), PJ_WKT2_2019, options) : nullptr;
  if (!wkt) throw BadInput("CRS '" + def + "': PROJ cannot write it as WKT2");
  return wkt;
}

}  // namespace

std::string engineering_crs_wkt(const std::string& map_name) {
  // WKT1 LOCAL_CS: what GDAL 3.6 and QGIS read as an engineering CRS (WKT2 ENGCRS).
  const std::string n = wkt_name(map_name);
  return "LOCAL_CS[\"fleetmap map frame " + n + "\",LOCAL_DATUM[\"fleetmap map " + n +
         "\",32767],UNIT[\"metre\",1,AUTHORITY[\"EPSG\",\"9001\"]],AXIS[\"X\",EAST],AXIS[\"Y\",NORTH]]";
}

std::string map_frame_crs_wkt(const std::string& map_name, const std::optional<MapGeoref>& georef) {
  if (!georef) return engineering_crs_wkt(map_name);
  const GeoTransform t(*georef);  // checks the base CRS and the similarity
  if (georef->frame_is_crs()) return t.base_wkt();
  std::string base = base_wkt2(georef->crs);
  if (base.rfind("PROJCRS[", 0) != 0) throw BadInput("CRS '" + georef->crs + "': expected a projected CRS");
  // base = t + k R(θ) map  =>  map = A base + (a0, b0), A = R(-θ) / k.
  const double c = std::cos(georef->rotation), s = std::sin(georef->rotation), k = georef->scale;
  const double a1 = c / k, a2 = s / k, b1 = -s / k, b2 = c / k;
  const double a0 = -(a1 * georef->tx + a2 * georef->ty), b0 = -(b1 * georef->tx + b2 * georef->ty);
  const auto coeff = [](const char* name, double v, int id) {
    return std::string(",PARAMETER[\"") + name + "\"," + num(v) + ",SCALEUNIT[\"coefficient\",1],ID[\"EPSG\"," +
           std::to_string(id) + "]]";
  };
  const auto offset = [](const char* name, double v, int id) {
    return std::string(",PARAMETER[\"") + name + "\"," + num(v) + ",LENGTHUNIT[\"metre\",1],ID[\"EPSG\"," +
           std::to_string(id) + "]]";
  };
  return "DERIVEDPROJCRS[\"fleetmap map frame " + wkt_name(map_name) + "\",BASE" + base +
         ",DERIVINGCONVERSION[\"fleetmap map frame similarity\","
         "METHOD[\"Affine parametric transformation\",ID[\"EPSG\",9624]]" +
         offset("A0", a0, 8623) + coeff("A1", a1, 8624) + coeff("A2", a2, 8625) + offset("B0", b0, 8639) +
         coeff("B1", b1, 8640) + coeff("B2", b2, 8641) +
         "],CS[Cartesian,2],AXIS[\"x\",east,ORDER[1],LENGTHUNIT[\"metre\",1]],"
         "AXIS[\"y\",north,ORDER[2],LENGTHUNIT[\"metre\",1]]]";
}

std::optional<MapGeoref> georef_from_frame_crs(const std::string& wkt) {
  if (wkt.rfind("DERIVEDPROJCRS[", 0) != 0) return std::nullopt;
  PJ_CONTEXT* ctx = proj_context_create();
  proj_log_level(ctx, PJ_LOG_NONE);
  PJ* crs = proj_create(ctx, wkt.c_str());
  PJ* base = crs ? proj_get_source_crs(ctx, crs) : nullptr;
  PJ* conversion = crs ? proj_crs_get_coordoperation(ctx, crs) : nullptr;
  PJ* cs = crs ? proj_crs_get_coordinate_system(ctx, crs) : nullptr;
  std::optional<MapGeoref> out;
  const char* code = nullptr;
  bool usable = base && conversion && cs && proj_get_type(base) == PJ_TYPE_PROJECTED_CRS &&
                proj_coordoperation_get_method_info(ctx, conversion, nullptr, nullptr, &code) && code &&
                std::string(code) == "9624" && proj_cs_get_axis_count(ctx, cs) == 2;
  for (int i = 0; usable && i < 2; ++i) {
    double factor = 0;
    usable = proj_cs_get_axis_info(ctx, cs, i, nullptr, nullptr, nullptr, &factor, nullptr, nullptr, nullptr) &&
             std::abs(factor - 1) < 1e-12;
  }
  std::map<std::string, double> p;
  for (int i = 0; usable && i < proj_coordoperation_get_param_count(ctx, conversion); ++i) {
    const char* name = nullptr;
    double value = 0, factor = 1;
    if (proj_coordoperation_get_param(ctx, conversion, i, &name, nullptr, nullptr, &value, nullptr, &factor, nullptr,
                                      nullptr, nullptr, nullptr) &&
        name)
      p[name] = value * factor;
  }
  usable = usable && p.size() == 6;
  for (const char* k : {"A0", "A1", "A2", "B0", "B1", "B2"}) usable = usable && p.count(k);
  const char* base_wkt = usable ? proj_as_wkt(ctx, base, PJ_WKT2_2019, nullptr) : nullptr;
  if (usable && base_wkt) {
    // map = R(-theta) (base - t) / k: A1 = B2 = cos/k, A2 = -B1 = sin/k (the writer above).
    const double a0 = p["A0"], a1 = p["A1"], a2 = p["A2"], b0 = p["B0"], b1 = p["B1"], b2 = p["B2"];
    const double det = a1 * b2 - a2 * b1, size = std::hypot(a1, a2);
    if (size > 0 && std::abs(a1 - b2) <= 1e-12 * size && std::abs(a2 + b1) <= 1e-12 * size)
      out = MapGeoref{base_wkt, (b0 * a2 - a0 * b2) / det, (a0 * b1 - b0 * a1) / det, std::atan2(a2, a1), 1 / size};
  }
  proj_destroy(cs);
  proj_destroy(conversion);
  proj_destroy(base);
  proj_destroy(crs);
  proj_context_destroy(ctx);
  return out;
}

}  // namespace fleetmap
