#include "server/cli/gis_import.h"

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <iostream>
#include <sstream>

#include "app/exit_codes.h"
#include "common/core/error.h"
#include "common/gis/ogr_import.h"
#include "protocol/map_store.h"
#include "protocol/scene_store.h"

namespace fleetmap {
namespace {

std::vector<double> numbers(const std::string& text, size_t n, const std::string& what) {
  std::vector<double> v;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ',')) {
    char* end = nullptr;
    const double d = std::strtod(item.c_str(), &end);
    if (end == item.c_str() || *end != '\0' || !std::isfinite(d)) break;
    v.push_back(d);
  }
  if (v.size() != n) throw UsageError(what + ": expected " + std::to_string(n) + " comma-separated numbers, got '" + text + "'");
  return v;
}

// Reading progress on stderr: a live line on a terminal, every 10 % otherwise.
std::function<void(double)> read_progress() {
  const bool tty = isatty(fileno(stderr));
  auto last = std::make_shared<int>(-1);
  return [tty, last](double f) {
    const int pct = static_cast<int>(100 * std::clamp(f, 0.0, 1.0));
    if (pct == *last) return;
    if (tty) std::fprintf(stderr, "\rreading: %d%%%s", pct, pct == 100 ? "\n" : "");
    else if (pct / 10 != *last / 10) std::fprintf(stderr, "reading: %d%%\n", pct);
    *last = pct;
  };
}

OgrImport read_gis(const std::string& file, const GisImportOptions& o, CliContext* ctx) {
  OgrImportOptions opt;
  if (!o.rules.empty()) opt.rules = read_import_rules(o.rules);
  opt.layers = o.layers;
  opt.crs = o.crs;
  if (!o.origin.empty()) {
    const auto v = numbers(o.origin, 2, "--origin");
    opt.origin = LonLat{v[1], v[0]};
  }
  if (!o.clip.empty()) {
    const auto v = numbers(o.clip, 4, "--clip");
    opt.clip = Clip{v[0], v[1], v[2], v[3]};
  }
  opt.clip_to_osm_bounds = !o.no_clip;
  opt.invalid = o.invalid == "refuse" ? InvalidPolicy::Refuse : InvalidPolicy::Repair;
  if (!o.frame_of.empty()) {
    if (!ctx) throw UsageError("--frame-of needs the database: use it with map import");
    MapInfo info = MapStore(ctx->connection()).info(o.frame_of);
    if (!info.georef) throw BadInput("--frame-of: map '" + o.frame_of + "' has no georeference");
    opt.frame = info.georef;
  }
  opt.progress = read_progress();
  return import_ogr(file, opt);
}

void print_report(const std::string& file, const OgrImport& r) {
  const OgrImportReport& rep = r.report;
  std::printf("%s: OGR driver %s, source CRS %s\n", file.c_str(), rep.driver.c_str(),
              rep.source_crs.empty() ? "none" : rep.source_crs.substr(0, 80).c_str());
  std::printf("map frame: %s\n", rep.frame.c_str());
  for (const auto& [name, l] : rep.layers) {
    std::printf("layer %s: %zu read, %zu kept, %zu obstacles, %zu segments, %zu objects", name.c_str(), l.read, l.kept,
                l.obstacles, l.segments, l.objects);
    if (l.repaired) std::printf(", %zu repaired", l.repaired);
    if (l.clipped) std::printf(", %zu clipped", l.clipped);
    if (l.repeated_vertices) std::printf(", %zu repeated vertices dropped", l.repeated_vertices);
    std::printf("\n");
    for (const auto& [why, n] : l.skipped) std::printf("  skipped %zu: %s\n", n, why.c_str());
  }
  for (const std::string& w : rep.warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
  std::printf("total: %zu obstacles, %zu segments, %zu objects\n", r.map.obstacles.size(), r.map.segment_count(),
              r.scene.objects.size());
  std::printf("extent (map frame, m): (%.3f, %.3f) to (%.3f, %.3f)\n", rep.extent.xmin, rep.extent.ymin,
              rep.extent.xmax, rep.extent.ymax);
  if (rep.extent_wgs84)
    std::printf("extent (WGS 84): lon %.7f to %.7f, lat %.7f to %.7f\n", rep.extent_wgs84->first.lon,
                rep.extent_wgs84->second.lon, rep.extent_wgs84->first.lat, rep.extent_wgs84->second.lat);
  else
    std::printf("extent (WGS 84): none, the map is not georeferenced (map georef NAME --control ...)\n");
}

}  // namespace

void add_gis_options(CLI::App* cmd, GisImportOptions& o) {
  cmd->add_option("--rules", o.rules, "GIS: rules file (JSON, docs/gis-import.md); default: built-in OSM or plain rules");
  cmd->add_option("--layer", o.layers, "GIS: read only this layer (repeatable)");
  cmd->add_option("--crs", o.crs, "GIS: the source CRS (EPSG:xxxx, WKT, PROJ), when the data has none or to override it");
  cmd->add_option("--origin", o.origin, "GIS: local projection origin LAT,LON for a geographic source")->type_name("LAT,LON");
  cmd->add_option("--frame-of", o.frame_of, "GIS: import into the frame of this stored, georeferenced map");
  cmd->add_option("--clip", o.clip, "GIS: keep only what lies inside MINLON,MINLAT,MAXLON,MAXLAT (cut at the edge)")
      ->type_name("W,S,E,N");
  cmd->add_flag("--no-clip", o.no_clip, "GIS: keep OSM features beyond the file's <bounds>");
  cmd->add_option("--invalid", o.invalid, "GIS: invalid polygons: repair (MakeValid) or refuse")
      ->check(CLI::IsMember({"repair", "refuse"}))
      ->capture_default_str();
}

bool use_ogr(const std::string& file, const std::string& format) {
  return format == "ogr" || (format == "auto" && is_ogr_source(file));
}

int run_gis_check(const std::string& file, const GisImportOptions& o, CliContext&) {
  print_report(file, read_gis(file, o, nullptr));
  std::printf("%s: ok\n", file.c_str());
  return exit_code::kOk;
}

MapImportReport run_gis_import(const std::string& file, const std::string& name, MapImportOptions options,
                               const GisImportOptions& o, CliContext& ctx) {
  const OgrImport r = read_gis(file, o, &ctx);
  print_report(file, r);
  const auto t0 = std::chrono::steady_clock::now();
  MapStore store(ctx.connection());
  // The map and its georeference in one transaction; the objects follow in theirs
  // (Transaction does not nest), and a failure there removes a new map again.
  options.georef = r.georef;
  const MapImportReport report = store.import(r.map, name, file, options);
  try {
    if (!r.scene.objects.empty())
      SceneStore(ctx.connection()).import(name, r.scene, {.replace = options.replace, .add_tags = true});
  } catch (...) {
    if (!report.replaced) store.remove(name);
    throw;
  }
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("%s '%s': %zu obstacles, %zu segments, %zu objects in %.2f s\n", report.replaced ? "replaced" : "imported",
              name.c_str(), r.map.obstacles.size(), r.map.segment_count(), r.scene.objects.size(), s);
  return report;
}

}  // namespace fleetmap
