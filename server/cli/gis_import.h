#pragma once
// map check|import of a GIS source read by OGR (common/gis/ogr_import.h): the options,
// the operator's report, the storing. map_commands.cpp dispatches here for GIS files.
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "app/cli_context.h"
#include "protocol/map_store.h"

namespace fleetmap {

struct GisImportOptions {
  std::string rules, crs, origin, frame_of, clip, invalid = "repair";
  std::vector<std::string> layers;
  bool no_clip = false;
};

void add_gis_options(CLI::App* cmd, GisImportOptions& o);

// format "ogr", or "auto" and a name OGR should read (is_ogr_source).
bool use_ogr(const std::string& file, const std::string& format);

int run_gis_check(const std::string& file, const GisImportOptions& o, CliContext& ctx);
// Reads the source, prints its report, stores the map with its georeference in one
// transaction (MapStore::import with options), then its objects. options.georef is
// set here from the source.
MapImportReport run_gis_import(const std::string& file, const std::string& name, MapImportOptions options,
                               const GisImportOptions& o, CliContext& ctx);

}  // namespace fleetmap
