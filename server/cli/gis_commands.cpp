#include "server/cli/gis_commands.h"

#include <cstdio>
#include <string>
#include <vector>

#include "app/exit_codes.h"
#include "common/gis/map_frame_crs.h"
#include "protocol/gis_layers.h"
#include "protocol/map_store.h"
#include "server/cli/command.h"

namespace fleetmap {

namespace {

// gis publish [MAP...]: the layers are a snapshot (robots, trajectories, GPS fixes move
// on); this refreshes them, e.g. from cron. Every map when none is named.
struct GisPublishArgs {
  std::vector<std::string> maps;
};

int run_gis_publish(const GisPublishArgs& a, CliContext& ctx) {
  MapStore store(ctx.connection());
  std::vector<MapInfo> maps;
  if (a.maps.empty()) maps = store.list();
  for (const std::string& name : a.maps) maps.push_back(store.info(name));  // MapNotFound: exit 4
  GisLayers layers(ctx.connection());
  if (maps.empty()) layers.withdraw(true);
  for (const MapInfo& m : maps) {
    layers.publish(m.name, map_frame_crs_wkt(m.name, m.georef), true);
    std::printf("published '%s': %zu layers in %s\n", m.name.c_str(), GisLayers::map_layer_names().size(),
                layers.database().c_str());
  }
  return exit_code::kOk;
}

void add_gis_publish(CLI::App& gis, CliContext& ctx) {
  auto a = std::make_shared<GisPublishArgs>();
  auto* cmd = gis.add_subcommand("publish", "rebuild the GIS layers of some maps (default: every map) and the "
                                            "GPS layer from the fleet tables");
  cmd->add_option("MAP", a->maps, "map names");
  run_with(*cmd, a, ctx, run_gis_publish);
}

// gis list: what GIS tools see, tab-separated: layer, geometry type, SRID.
struct GisListArgs {};

int run_gis_list(const GisListArgs&, CliContext& ctx) {
  GisLayers layers(ctx.connection());
  for (const GisLayerInfo& l : layers.layers())
    std::printf("%s\t%s\t%d\n", l.table.c_str(), l.geometry_type.c_str(), l.srid);
  return exit_code::kOk;
}

void add_gis_list(CLI::App& gis, CliContext& ctx) {
  auto* cmd = gis.add_subcommand("list", "the GIS layers (database <db>_gis): layer, geometry type, SRID");
  run_with(*cmd, std::make_shared<GisListArgs>(), ctx, run_gis_list);
}

}  // namespace

void add_gis_commands(CLI::App& app, CliContext& ctx) {
  auto* gis = app.add_subcommand("gis", "the database as GIS layers for QGIS, ogrinfo, ogr2ogr (docs/gis-layers.md)");
  gis->require_subcommand(1);
  add_gis_publish(*gis, ctx);
  add_gis_list(*gis, ctx);
}

}  // namespace fleetmap
