#include "server/cli/georef_command.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/exit_codes.h"
#include "common/core/error.h"
#include "common/gis/control_point_fit.h"
#include "common/gis/crs_name.h"
#include "common/gis/geo_transform.h"
#include "protocol/georef_store.h"
#include "protocol/map_store.h"
#include "server/cli/command.h"
#include "server/cli/gis_publish.h"

namespace fleetmap {
namespace {

struct MapGeorefArgs {
  std::string name;
  std::optional<double> lat, lon;
  std::optional<double> heading;
  std::vector<std::string> controls;
  bool allow_scale = false;
  std::string crs;
  std::string offset;
  std::optional<double> rotation;
  bool clear = false;
};

// "1.5,-2,45.7,3.1" -> its n numbers; throws BadInput naming what (e.g. "--control 2").
std::vector<double> numbers(const std::string& text, size_t n, const std::string& what, const std::string& form) {
  std::vector<double> out;
  const char* p = text.data();
  const char* end = p + text.size();
  for (;;) {
    const char* comma = std::find(p, end, ',');
    double v = 0;
    auto [q, ec] = std::from_chars(p, comma, v);
    if (ec != std::errc() || q != comma || !std::isfinite(v)) {
      out.clear();
      break;
    }
    out.push_back(v);
    if (comma == end) break;
    p = comma + 1;
  }
  if (out.size() != n)
    throw BadInput(what + ": expected " + form + " (" + std::to_string(n) + " numbers), got '" + text + "'");
  return out;
}

std::string fix_text(LonLat ll) {
  char b[64];
  std::snprintf(b, sizeof b, "lat %.9f, lon %.9f", ll.lat, ll.lon);
  return b;
}

std::string where(const GeoTransform& t, Point p) {
  try {
    return fix_text(t.to_wgs84(p));
  } catch (const BadInput&) {
    return "outside the domain of the base CRS";
  }
}

void print_control_points(const std::vector<StoredControlPoint>& points) {
  double sq = 0;
  for (const StoredControlPoint& p : points) sq += p.residual_m * p.residual_m;
  std::printf("  control points: %zu, rms %.4f m\n", points.size(),
              points.empty() ? 0.0 : std::sqrt(sq / static_cast<double>(points.size())));
  std::printf("    %3s %14s %14s %15s %15s %12s\n", "", "x (m)", "y (m)", "lat", "lon", "residual (m)");
  for (size_t i = 0; i < points.size(); ++i) {
    const StoredControlPoint& p = points[i];
    std::printf("    %3zu %14.4f %14.4f %15.9f %15.9f %12.4f\n", i + 1, p.x, p.y, p.lat, p.lon, p.residual_m);
  }
}

// map georef NAME: what an operator needs to check a georeference by eye.
int print_georef(const std::string& name, CliContext& ctx) {
  MapStore maps(ctx.connection());
  const MapInfo info = maps.info(name);
  if (!info.georef) {
    std::printf("map '%s': not georeferenced\n", name.c_str());
    return exit_code::kOk;
  }
  const MapGeoref& g = *info.georef;
  std::printf("map '%s': georeferenced\n", name.c_str());
  std::printf("  base CRS: %s\n    %s\n", crs_name(g.crs).c_str(), g.crs.c_str());
  std::printf("  similarity: base = (tx, ty) + scale * R(rotation) * map%s\n",
              g.frame_is_crs() ? " (identity: the map frame is the base CRS)" : "");
  std::printf("    tx, ty:   %.4f, %.4f\n", g.tx, g.ty);
  std::printf("    rotation: %.9f rad (%.6f deg)\n", g.rotation, g.rotation * 180 / M_PI);
  std::printf("    scale:    %.9f\n", g.scale);
  const GeoTransform t(g);
  const Border& b = info.border;
  std::printf("  map origin (0, 0): %s\n", where(t, {0, 0}).c_str());
  std::printf("  border corners:\n");
  for (const Point p : {Point{b.mx1, b.my1}, Point{b.mx4, b.my1}, Point{b.mx4, b.my4}, Point{b.mx1, b.my4}})
    std::printf("    (%.3f, %.3f): %s\n", p.x, p.y, where(t, p).c_str());
  const std::vector<StoredControlPoint> points = GeorefStore(ctx.connection()).control_points(name);
  if (!points.empty()) print_control_points(points);
  return exit_code::kOk;
}

// --control: the fit, printed point by point before anything is stored.
int fit(const MapGeorefArgs& a, CliContext& ctx) {
  std::vector<ControlPoint> cps;
  for (size_t i = 0; i < a.controls.size(); ++i) {
    const auto v = numbers(a.controls[i], 4, "--control " + std::to_string(i + 1), "x,y,lat,lon");
    cps.push_back({{v[0], v[1]}, {v[3], v[2]}});
  }
  MapStore(ctx.connection()).info(a.name);  // MapNotFound before the work
  const ControlPointFit f = fit_control_points(cps);
  std::vector<StoredControlPoint> stored;
  for (size_t i = 0; i < cps.size(); ++i) {
    stored.push_back({cps[i].map.x, cps[i].map.y, cps[i].fix.lat, cps[i].fix.lon, f.residuals[i]});
    std::printf("control point %zu: (%.4f, %.4f) <-> %s: residual %.4f m\n", i + 1, cps[i].map.x, cps[i].map.y,
                fix_text(cps[i].fix).c_str(), f.residuals[i]);
  }
  std::printf("rms %.4f m over %zu points; scale %.9f (%+.4f %%); rotation %.9f rad (%.6f deg)\n", f.rms, cps.size(),
              f.scale, (f.scale - 1) * 100, f.georef.rotation, f.georef.rotation * 180 / M_PI);
  if (cps.size() == 2)
    std::printf("note: two points fit any similarity exactly; a third one would check the fit\n");
  if (std::abs(f.scale - 1) > kScaleTolerance) {
    char b[256];
    std::snprintf(b, sizeof b,
                  "control points: the fit's scale is %.6g (map metres to ground metres); expected 1 within %g %% "
                  "for a map in metres (are the map's units or the points wrong?); --allow-scale keeps it",
                  f.scale, kScaleTolerance * 100);
    if (!a.allow_scale) throw BadInput(b);
    std::fprintf(stderr, "warning: scale %.6g kept (--allow-scale)\n", f.scale);
  }
  GeorefStore(ctx.connection()).set_fitted(a.name, f.georef, stored);
  publish_gis_layers(ctx.connection(), a.name);
  std::printf("map '%s' georeferenced by %zu control points\n", a.name.c_str(), cps.size());
  return exit_code::kOk;
}

int run_map_georef(const MapGeorefArgs& a, CliContext& ctx) {
  const bool origin = a.lat || a.lon, control = !a.controls.empty(), crs = !a.crs.empty();
  const int modes = origin + control + crs + a.clear;
  if (modes > 1) throw UsageError("expected one of LAT LON, --control, --crs or --clear");
  if (a.heading && !origin) throw UsageError("--heading goes with LAT LON");
  if ((!a.offset.empty() || a.rotation) && !crs) throw UsageError("--offset and --rotation go with --crs");
  if (a.allow_scale && !control) throw UsageError("--allow-scale goes with --control");
  if (modes == 0) return print_georef(a.name, ctx);
  if (control) return fit(a, ctx);

  MapStore store(ctx.connection());
  if (a.clear) {
    store.set_georef(a.name, std::nullopt);
    publish_gis_layers(ctx.connection(), a.name);
    std::printf("map '%s' is no longer georeferenced\n", a.name.c_str());
    return exit_code::kOk;
  }
  MapGeoref g;
  if (origin) {
    if (!a.lat || !a.lon) throw BadInput("expected LAT and LON");
    const double heading = a.heading.value_or(0);
    if (!std::isfinite(heading)) throw BadInput("expected a finite --heading");
    g = georef_from_origin(*a.lat, *a.lon, heading);
  } else {
    g.crs = a.crs;
    if (!a.offset.empty()) {
      const auto v = numbers(a.offset, 2, "--offset", "TX,TY");
      g.tx = v[0];
      g.ty = v[1];
    }
    g.rotation = a.rotation.value_or(0);
  }
  const GeoTransform check(g);  // throws BadInput when PROJ cannot use it
  store.set_georef(a.name, g);
  publish_gis_layers(ctx.connection(), a.name);
  std::printf("map '%s' georeferenced\n", a.name.c_str());
  return exit_code::kOk;
}

}  // namespace

void add_map_georef(CLI::App& map, CliContext& ctx) {
  auto a = std::make_shared<MapGeorefArgs>();
  auto* cmd = map.add_subcommand(
      "georef", "print or set a map's georeference (SendGPS fixes and WGS 84 exports go through it)");
  cmd->add_option("NAME", a->name, "map name")->required();
  cmd->add_option("LAT", a->lat, "latitude of the map origin (degrees, WGS 84)")->check(CLI::Range(-90.0, 90.0));
  cmd->add_option("LON", a->lon, "longitude of the map origin (degrees)")->check(CLI::Range(-180.0, 180.0));
  cmd->add_option("--heading", a->heading, "with LAT LON: direction of the map x axis, radians counter-clockwise from east (default 0)");
  cmd->add_option("--control", a->controls,
                  "a control point, map metres and WGS 84 degrees; >= 2 give a least-squares fit")
      ->type_name("X,Y,LAT,LON")
      ->allow_extra_args(false);
  cmd->add_flag("--allow-scale", a->allow_scale,
                "with --control: keep a fitted scale further than 1 % from 1 (a map not in metres)");
  cmd->add_option("--crs", a->crs, "the projected, metric CRS the map frame sits in (EPSG:26910, WKT, PROJ string)");
  cmd->add_option("--offset", a->offset, "with --crs: TX,TY, the CRS coordinates of the map origin")->type_name("TX,TY");
  cmd->add_option("--rotation", a->rotation, "with --crs: the map x axis in the CRS, radians counter-clockwise");
  cmd->add_flag("--clear", a->clear, "remove the georeference and its control points");
  run_with(*cmd, a, ctx, run_map_georef);
}

}  // namespace fleetmap
