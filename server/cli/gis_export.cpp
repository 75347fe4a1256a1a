#include "server/cli/gis_export.h"

#include <cstdio>
#include <set>

#include "common/core/error.h"
#include "server/core/geojson_frame.h"

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
  return geojson_frame(a.crs, name, georef);
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
