#include "server/cli/topo_commands.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>

#include "common/geometry/number_format.h"
#include "common/io/topo_geojson.h"
#include "server/cli/gis_export.h"
#include "common/io/topo_json.h"
#include "protocol/map_store.h"
#include "protocol/topo_store.h"
#include "app/exit_codes.h"
#include "app/maps_dir.h"
#include "common/core/error.h"
#include "server/cli/command.h"
#include "server/cli/map_source.h"
#include "server/cli/tour_command.h"

namespace fleetmap {
namespace {

// "corridor 106, stairs 8"
std::string count_types(const TopoGraph& g) {
  std::map<EdgeType, size_t> by_type;
  for (const TopoEdge& e : g.edges()) ++by_type[e.type];
  std::string s;
  for (auto [t, c] : by_type) s += (s.empty() ? "" : ", ") + std::string(to_string(t)) + " " + std::to_string(c);
  return s;
}

std::string describe(const TopoGraph& g) {
  return std::to_string(g.nodes().size()) + " nodes, " + std::to_string(g.edges().size()) + " edges (" +
         count_types(g) + "), " + std::to_string(g.components()) + " connected component" + (g.components() == 1 ? "" : "s");
}

// A route end: a node id, or "X,Y" for the node nearest that point.
int resolve_end(const TopoGraph& g, const std::string& arg, const char* which) {
  const char* b = arg.data();
  const char* e = b + arg.size();
  if (auto comma = arg.find(','); comma != std::string::npos) {
    double x = 0, y = 0;
    auto rx = std::from_chars(b, b + comma, x);
    auto ry = std::from_chars(b + comma + 1, e, y);
    if (rx.ec != std::errc() || rx.ptr != b + comma || ry.ec != std::errc() || ry.ptr != e || !std::isfinite(x) ||
        !std::isfinite(y))
      throw BadInput(std::string("expected a node id or X,Y for ") + which + ", got '" + arg + "'");
    const auto id = g.nearest_node({x, y});
    if (!id) throw TopoNodeNotFound(-1);
    std::fprintf(stderr, "%s (%s, %s): nearest node %d at %.3f m\n", which, format_number(x).c_str(),
                 format_number(y).c_str(), *id, distance(g.node(*id).pos, {x, y}));
    return *id;
  }
  int id = -1;
  auto r = std::from_chars(b, e, id);
  if (r.ec != std::errc() || r.ptr != e || id < 0)
    throw BadInput(std::string("expected a node id or X,Y for ") + which + ", got '" + arg + "'");
  return id;
}

// topo check FILE: validate a navigation graph, no database.
struct TopoCheckArgs {
  std::string file;
};

int run_topo_check(const TopoCheckArgs& a, CliContext&) {
  const TopoGraph g = read_topo_json_file(a.file);
  std::cout << a.file << ": ok: " << describe(g) << "\n";
  return exit_code::kOk;
}

void add_topo_check(CLI::App& topo, CliContext& ctx) {
  auto a = std::make_shared<TopoCheckArgs>();
  auto* cmd = topo.add_subcommand("check", "validate a navigation graph (JSON) without touching the database");
  cmd->add_option("FILE", a->file, "navigation graph, e.g. " + real_map_path("UT_Campus.navigation.json"))->required();
  run_with(*cmd, a, ctx, run_topo_check);
}

// topo import MAP FILE [--replace]: one transaction.
struct TopoImportArgs {
  std::string map, file;
  bool replace = false;
};

int run_topo_import(const TopoImportArgs& a, CliContext& ctx) {
  if (auto e = check_map_name(a.map)) throw BadInput(*e);
  const TopoGraph g = read_topo_json_file(a.file);
  // Nodes outside the map's border are allowed (the map may be a part), but worth a word.
  const Rect border = MapStore(ctx.connection()).info(a.map).border.rect();
  size_t outside = 0;
  for (const TopoNode& n : g.nodes()) outside += !border.contains(n.pos);
  if (outside) std::cerr << "warning: " << outside << " nodes lie outside the border of map '" << a.map << "'\n";
  TopoStore(ctx.connection()).import(a.map, g, a.file, a.replace);
  std::cout << "imported graph of '" << a.map << "': " << describe(g) << "\n";
  return exit_code::kOk;
}

void add_topo_import(CLI::App& topo, CliContext& ctx) {
  auto a = std::make_shared<TopoImportArgs>();
  auto* cmd = topo.add_subcommand("import", "store the navigation graph of a stored map (one transaction)");
  cmd->add_option("MAP", a->map, "name of a stored map")->required();
  cmd->add_option("FILE", a->file, "navigation graph (JSON)")->required();
  cmd->add_flag("--replace", a->replace, "replace the map's graph if it has one");
  run_with(*cmd, a, ctx, run_topo_import);
}

// topo route MAP FROM TO [--no-stairs] [--radius R]
struct TopoRouteArgs {
  std::string map, from, to;
  RouteOptions options;
};

int run_topo_route(const TopoRouteArgs& a, CliContext& ctx) {
  if (!std::isfinite(a.options.radius)) throw BadInput("expected a finite --radius");
  const TopoGraph g = TopoStore(ctx.connection()).load(a.map);
  const int from = resolve_end(g, a.from, "FROM"), to = resolve_end(g, a.to, "TO");
  const auto r = g.route(from, to, a.options);
  if (!r) {
    std::fprintf(stderr, "fleetmap: no route from %d to %d on '%s'%s (radius %s m)\n", from, to, a.map.c_str(),
                 a.options.avoid_stairs ? " without stairs" : "", format_number(a.options.radius).c_str());
    return exit_code::kNoPath;
  }
  for (size_t i = 0; i < r->nodes.size(); ++i) {
    const Point p = g.node(r->nodes[i]).pos;
    const std::string via = i == 0 ? "-" : std::string(to_string(g.edges()[r->edges[i - 1]].type));
    std::printf("%d %s %s %s\n", r->nodes[i], format_number(p.x).c_str(), format_number(p.y).c_str(), via.c_str());
  }
  std::printf("length %.3f\n", r->length);
  return exit_code::kOk;
}

void add_topo_route(CLI::App& topo, CliContext& ctx) {
  auto a = std::make_shared<TopoRouteArgs>();
  auto* cmd = topo.add_subcommand(
      "route", "shortest route between two nodes: one line 'ID X Y EDGE-TYPE' per node, then 'length L'");
  cmd->add_option("MAP", a->map, "name of a stored map with a graph")->required();
  cmd->add_option("FROM", a->from, "start: node id, or X,Y for the nearest node")->type_name("ID|X,Y")->required();
  cmd->add_option("TO", a->to, "goal: node id, or X,Y for the nearest node")->type_name("ID|X,Y")->required();
  cmd->add_flag("--no-stairs", a->options.avoid_stairs, "a wheeled robot: do not use stairs edges");
  cmd->add_option("--radius", a->options.radius, "robot radius (m): only edges with max_clearance >= radius")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  run_with(*cmd, a, ctx, run_topo_route);
}

// topo export MAP [--format json|geojson|gpkg|fgb|DRIVER] [--crs map|wgs84|base] [-o FILE]
struct TopoExportArgs {
  std::string map, format = "json", out;
  GisExportArgs gis;
};

int run_topo_export(const TopoExportArgs& a, CliContext& ctx) {
  const TopoGraph g = TopoStore(ctx.connection()).load(a.map);
  if (a.format == "json") {
    write_output(write_topo_json(g), a.out);
    return exit_code::kOk;
  }
  const MapInfo info = MapStore(ctx.connection()).info(a.map);
  if (a.format == "geojson") {
    write_output(write_topo_geojson(g, a.map, geojson_frame(a.gis, a.map, info.georef)), a.out);
  } else {
    OgrExport e(a.out, ogr_export_options(a.gis, a.format, a.out, a.map, info.georef));
    e.add_topology(g);
    finish_ogr_export(e, a.out);
  }
  return exit_code::kOk;
}

void add_topo_export(CLI::App& topo, CliContext& ctx) {
  auto a = std::make_shared<TopoExportArgs>();
  auto* cmd = topo.add_subcommand("export", "write a stored graph as navigation JSON, GeoJSON or GIS layers");
  cmd->add_option("MAP", a->map, "name of a stored map with a graph")->required();
  cmd->add_option("--format", a->format,
                  "json (the import format, map frame), geojson, gpkg, fgb or a GDAL vector driver's short name")
      ->capture_default_str();
  cmd->add_option("-o,--output", a->out, "output file (default: standard output; GDAL formats need one)");
  add_gis_export_options(cmd, a->gis);
  run_with(*cmd, a, ctx, run_topo_export);
}

// topo delete MAP: the graph goes, the map stays.
struct TopoDeleteArgs {
  std::string map;
};

int run_topo_delete(const TopoDeleteArgs& a, CliContext& ctx) {
  if (!TopoStore(ctx.connection()).remove(a.map)) throw TopoGraphNotFound(a.map);
  std::cout << "deleted the graph of '" << a.map << "'\n";
  return exit_code::kOk;
}

void add_topo_delete(CLI::App& topo, CliContext& ctx) {
  auto a = std::make_shared<TopoDeleteArgs>();
  auto* cmd = topo.add_subcommand("delete", "delete the graph of a stored map (the map stays)");
  cmd->add_option("MAP", a->map, "map name")->required();
  run_with(*cmd, a, ctx, run_topo_delete);
}

}  // namespace

void add_topo_commands(CLI::App& app, CliContext& ctx) {
  // seed 003: topological maps beside the metric one.
  auto* topo = app.add_subcommand("topo", "topological maps: import, route, export and delete graphs");
  topo->require_subcommand(1);
  topo->footer("Exit codes: 0 ok, 1 failure (database, I/O), 2 malformed file or argument, 3 no route, "
               "4 unknown map, graph or node, or a graph exists (import without --replace), 64 usage.");
  add_topo_check(*topo, ctx);
  add_topo_import(*topo, ctx);
  add_topo_route(*topo, ctx);
  add_topo_export(*topo, ctx);
  add_topo_delete(*topo, ctx);
  add_topo_tour_commands(*topo, ctx);
}

}  // namespace fleetmap
