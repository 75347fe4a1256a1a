#include "server/cli/map_export_command.h"

#include <memory>
#include <optional>

#include "app/exit_codes.h"
#include "common/gis/ogr_export.h"
#include "common/io/map_geojson.h"
#include "common/io/map_svg.h"
#include "common/io/seed_format.h"
#include "protocol/fleet_store.h"
#include "protocol/map_store.h"
#include "protocol/scene_store.h"
#include "protocol/topo_store.h"
#include "server/cli/command.h"
#include "server/cli/gis_export.h"
#include "server/cli/map_source.h"

namespace fleetmap {
namespace {

struct MapExportArgs {
  std::string name, format = "seed", out, since;
  bool trajectories = false;
  GisExportArgs gis;
};

std::optional<std::string> since_of(const MapExportArgs& a) {
  if (a.since.empty()) return std::nullopt;
  return a.since;
}

void export_ogr(const MapExportArgs& a, CliContext& ctx, const MapInfo& info, const Map& m) {
  OgrExport e(a.out, ogr_export_options(a.gis, a.format, a.out, a.name, info.georef));
  e.add_map(m);
  e.add_scene(SceneStore(ctx.connection()).load(a.name));
  try {
    e.add_topology(TopoStore(ctx.connection()).load(a.name));
  } catch (const TopoGraphNotFound&) {
    // a map without a graph: no topology layers
  }
  if (a.trajectories) {
    FleetStore fleet(ctx.connection());
    e.add_tracks(load_map_tracks(fleet, a.name, since_of(a)));
  }
  finish_ogr_export(e, a.out);
}

int run_map_export(const MapExportArgs& a, CliContext& ctx) {
  MapStore store(ctx.connection());
  const MapInfo info = store.info(a.name);
  const Map m = store.load(a.name);
  if (is_ogr_format(a.format)) {
    export_ogr(a, ctx, info, m);
    return exit_code::kOk;
  }
  std::string text;
  if (a.format == "seed") {
    text = write_seed(m);
  } else if (a.format == "geojson") {
    text = write_geojson(m, a.name, geojson_frame(a.gis, a.name, info.georef));
  } else {
    SvgOptions so;
    so.title = a.name;
    if (a.trajectories) {
      FleetStore fleet(ctx.connection());
      for (const Track& t : load_map_tracks(fleet, a.name, since_of(a))) {
        SvgTrack track;
        track.label = t.robot;
        for (const TrackPose& p : t.poses) track.points.push_back(p.pos);
        so.tracks.push_back(std::move(track));
      }
    }
    text = write_svg(m, so);
  }
  write_output(text, a.out);
  return exit_code::kOk;
}

}  // namespace

void add_map_export(CLI::App& map, CliContext& ctx) {
  auto a = std::make_shared<MapExportArgs>();
  auto* cmd = map.add_subcommand("export", "write a stored map as seed text, GeoJSON, SVG or GIS layers (GDAL)");
  cmd->add_flag("--trajectories", a->trajectories, "svg, GDAL formats: the trajectories of the map's robots");
  cmd->add_option("--since", a->since, "with --trajectories: only poses since this timestamp or age (10m, 2h)")
      ->type_name("TIME|AGE");
  cmd->add_option("NAME", a->name, "map name")->required();
  cmd->add_option("--format", a->format,
                  "seed, geojson, svg, gpkg (GeoPackage), fgb (FlatGeobuf) or a GDAL vector driver's short name")
      ->capture_default_str();
  cmd->add_option("-o,--output", a->out, "output file (default: standard output; GDAL formats need one)");
  add_gis_export_options(cmd, a->gis);
  run_with(*cmd, a, ctx, run_map_export);
}

}  // namespace fleetmap
