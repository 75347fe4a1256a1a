#pragma once
// What the export commands (map export, objects export, topo export, trajectory) share
// for GIS tools: the --crs and --layer options, the frame of a GeoJSON file and the OGR
// writer's options (common/gis/ogr_export.h).
//
// GeoJSON is WGS 84 longitude/latitude (RFC 7946 section 4), so a georeferenced map is
// written in WGS 84 by default; map-frame metres only with --crs map (the prior
// arrangement of section 4, said by the "fleetmap" member; the browser console reads
// it). A map without a georeference has no WGS 84: its GeoJSON needs --crs map, or a
// format that carries the map frame's CRS (--format gpkg).
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "common/gis/ogr_export.h"
#include "common/io/output_frame.h"
#include "common/map/map_georef.h"
#include "protocol/fleet_store.h"
#include "server/core/robot_tracks.h"  // load_track, load_map_tracks: the exports' tracks

namespace fleetmap {

struct GisExportArgs {
  std::string crs;                  // "" (the format's default), map, base, wgs84
  std::vector<std::string> layers;  // OGR: only these layers
};

void add_gis_export_options(CLI::App* cmd, GisExportArgs& a);

// The formats written by our own writers; any other --format is a GDAL vector driver.
bool is_ogr_format(const std::string& format);

// The frame of a GeoJSON export of map `name` (server/core/geojson_frame.h, shared with
// the web API). Throws BadInput when the map has no georeference and --crs is not map,
// or for --crs base (GeoJSON has no CRS member).
OutputFrame geojson_frame(const GisExportArgs& a, const std::string& name, const std::optional<MapGeoref>& georef);

// Throws BadInput for an empty output path (a GDAL driver writes files, not standard
// output) or an unknown driver.
OgrExportOptions ogr_export_options(const GisExportArgs& a, const std::string& format, const std::string& out,
                                    const std::string& name, const std::optional<MapGeoref>& georef);

// Closes the file and prints its layers and feature counts on stderr.
void finish_ogr_export(OgrExport& e, const std::string& out);

}  // namespace fleetmap
