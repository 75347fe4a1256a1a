#include "server/cli/gis_export.h"

#include <cstdio>
#include <set>

#include "common/core/error.h"
#include "common/gis/wgs84_frame.h"

namespace fleetmap {

void add_gis_export_options(CLI::App* cmd, GisExportArgs& a) {
  cmd->add_option("--crs", a.crs,
                  "frame of the coordinates: wgs84 (GeoJSON's default for a georeferenced map), map (map-frame "
                  "metres; the default of GDAL formats, which carry the map's CRS), base (the map's base CRS, GDAL "
                  "formats only)")
      ->check(CLI::IsMember({"map", "base", "wgs84"}));
  cmd->add_option("--layer", a.layers, "GDAL formats: only this layer (repeatable; one for single-layer drivers)");
}

bool is_ogr_format(const std::string& format) {
  static const std::set<std::string> kOwn{"seed", "geojson", "svg", "json", "csv"};
  return !kOwn.count(format);
}

OutputFrame geojson_frame(const GisExportArgs& a, const std::string& name, const std::optional<MapGeoref>& georef) {
  if (a.crs == "map") return {};
  if (a.crs == "base")
    throw BadInput("--crs base: GeoJSON holds WGS 84 (RFC 7946) or, by arrangement, the map frame; the base CRS "
                   "needs a format that says its CRS (--format gpkg or fgb)");
  if (!georef)
    throw BadInput("map '" + name + "' has no georeference, and GeoJSON is WGS 84 longitude/latitude (RFC 7946): "
                   "give --crs map for map-frame metres, --format gpkg for the map frame with its CRS, or "
                   "georeference the map (fleetmap map georef)");
  return wgs84_frame(*georef);
}

OgrExportOptions ogr_export_options(const GisExportArgs& a, const std::string& format, const std::string& out,
                                    const std::string& name, const std::optional<MapGeoref>& georef) {
  if (out.empty()) throw BadInput("--format " + format + ": expected -o FILE (GDAL drivers write files)");
  OgrExportOptions o;
  o.format = format;
  o.crs = parse_export_crs(a.crs.empty() ? "map" : a.crs);
  o.map_name = name;
  o.georef = georef;
  o.only_layers = {a.layers.begin(), a.layers.end()};
  return o;
}

Track load_track(FleetStore& fleet, const std::string& robot, const std::optional<std::string>& since) {
  Track t;
  t.robot = robot;
  for (const TrajectoryPoint& p : fleet.trajectory(robot, since)) t.poses.push_back({p.t_utc, {p.x, p.y}, p.theta, p.v});
  return t;
}

std::vector<Track> load_map_tracks(FleetStore& fleet, const std::string& map, const std::optional<std::string>& since) {
  std::vector<Track> out;
  for (const RobotStatus& r : fleet.status()) {
    if (r.map != map) continue;
    Track t = load_track(fleet, r.name, since);
    if (!t.poses.empty()) out.push_back(std::move(t));
  }
  return out;
}

void finish_ogr_export(OgrExport& e, const std::string& out) {
  e.close();
  std::fprintf(stderr, "%s:", out.c_str());
  const char* sep = " ";
  for (const OgrLayerReport& l : e.layers()) {
    std::fprintf(stderr, "%s%s %zu", sep, l.name.c_str(), l.features);
    if (l.repaired) std::fprintf(stderr, " (%zu polygons made valid)", l.repaired);
    sep = ", ";
  }
  std::fprintf(stderr, "%s\n", e.layers().empty() ? " no features" : "");
}

}  // namespace fleetmap
