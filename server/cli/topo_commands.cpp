#include "server/cli/topo_commands.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>

#include "common/geometry/number_format.h"
#include "common/io/topo_geojson.h"
#include "common/io/topo_json.h"
#include "protocol/map_store.h"
#include "protocol/topo_store.h"
#include "app/exit_codes.h"
#include "app/maps_dir.h"
#include "server/cli/map_source.h"

namespace fleetmap {
namespace {

// Runs a command body (which returns its exit code) and turns our errors into exit codes here, so that fleetmap_main
// needs no knowledge of them; anything else goes on to main's handlers.
void guarded(int* exit_code, const std::function<int()>& body) {
  try {
    *exit_code = body();
  } catch (const TopoFormatError& e) {
    std::cerr << e.what() << "\n";
    *exit_code = exit_code::kBadInput;
  } catch (const MapNotFound& e) {
    std::cerr << "fleetmap: " << e.what() << "\n";
    *exit_code = exit_code::kNotFound;
  } catch (const TopoGraphNotFound& e) {
    std::cerr << "fleetmap: " << e.what() << "\n";
    *exit_code = exit_code::kNotFound;
  } catch (const TopoGraphExists& e) {
    std::cerr << "fleetmap: " << e.what() << "\n";
    *exit_code = exit_code::kNotFound;
  } catch (const TopoNodeNotFound& e) {
    std::cerr << "fleetmap: " << e.what() << "\n";
    *exit_code = exit_code::kNotFound;
  }
}

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
      throw std::invalid_argument(std::string("expected a node id or X,Y for ") + which + ", got '" + arg + "'");
    const auto id = g.nearest_node({x, y});
    if (!id) throw TopoNodeNotFound(-1);
    std::fprintf(stderr, "%s (%s, %s): nearest node %d at %.3f m\n", which, format_number(x).c_str(),
                 format_number(y).c_str(), *id, distance(g.node(*id).pos, {x, y}));
    return *id;
  }
  int id = -1;
  auto r = std::from_chars(b, e, id);
  if (r.ec != std::errc() || r.ptr != e || id < 0)
    throw std::invalid_argument(std::string("expected a node id or X,Y for ") + which + ", got '" + arg + "'");
  return id;
}


}  // namespace

void add_topo_commands(CLI::App& app, CliContext& ctx, int* exit_code) {
  auto* topo = app.add_subcommand("topo", "topological maps (seed 003): import, route, export and delete graphs");
  topo->require_subcommand(1);
  topo->footer("Exit codes: 0 ok, 1 failure (database, I/O), 2 malformed file or argument, 3 no route, "
               "4 unknown map, graph or node, or a graph exists (import without --replace), 64 usage.");

  // topo check
  {
    auto file = std::make_shared<std::string>();
    auto* cmd = topo->add_subcommand("check", "validate a navigation graph (JSON) without touching the database");
    cmd->add_option("FILE", *file, "navigation graph, e.g. " + real_map_path("UT_Campus.navigation.json"))->required();
    cmd->callback([=] {
      guarded(exit_code, [&]() -> int {
        const TopoGraph g = read_topo_json_file(*file);
        std::cout << *file << ": ok: " << describe(g) << "\n";
        return exit_code::kOk;
      });
    });
  }

  // topo import
  {
    auto map = std::make_shared<std::string>();
    auto file = std::make_shared<std::string>();
    auto replace = std::make_shared<bool>(false);
    auto* cmd = topo->add_subcommand("import", "store the navigation graph of a stored map (one transaction)");
    cmd->add_option("MAP", *map, "name of a stored map")->required();
    cmd->add_option("FILE", *file, "navigation graph (JSON)")->required();
    cmd->add_flag("--replace", *replace, "replace the map's graph if it has one");
    cmd->callback([=, &ctx] {
      guarded(exit_code, [&]() -> int {
        if (auto e = check_map_name(*map)) throw std::invalid_argument(*e);
        const TopoGraph g = read_topo_json_file(*file);
        // Nodes outside the map's border are allowed (the map may be a part), but worth a word.
        const Rect border = MapStore(ctx.connection()).info(*map).border.rect();
        size_t outside = 0;
        for (const TopoNode& n : g.nodes()) outside += !border.contains(n.pos);
        if (outside) std::cerr << "warning: " << outside << " nodes lie outside the border of map '" << *map << "'\n";
        TopoStore(ctx.connection()).import(*map, g, *file, *replace);
        std::cout << "imported graph of '" << *map << "': " << describe(g) << "\n";
        return exit_code::kOk;
      });
    });
  }

  // topo route
  {
    auto map = std::make_shared<std::string>();
    auto from = std::make_shared<std::string>(), to = std::make_shared<std::string>();
    auto opt = std::make_shared<RouteOptions>();
    auto* cmd = topo->add_subcommand(
        "route", "shortest route between two nodes: one line 'ID X Y EDGE-TYPE' per node, then 'length L'");
    cmd->add_option("MAP", *map, "name of a stored map with a graph")->required();
    cmd->add_option("FROM", *from, "start: node id, or X,Y for the nearest node")->required();
    cmd->add_option("TO", *to, "goal: node id, or X,Y for the nearest node")->required();
    cmd->add_flag("--no-stairs", opt->avoid_stairs, "a wheeled robot: do not use stairs edges");
    cmd->add_option("--radius", opt->radius, "robot radius (m): only edges with max_clearance >= radius")
        ->check(CLI::NonNegativeNumber)
        ->capture_default_str();
    cmd->callback([=, &ctx] {
      guarded(exit_code, [&]() -> int {
        if (!std::isfinite(opt->radius)) throw std::invalid_argument("expected a finite --radius");
        const TopoGraph g = TopoStore(ctx.connection()).load(*map);
        const int a = resolve_end(g, *from, "FROM"), b = resolve_end(g, *to, "TO");
        const auto r = g.route(a, b, *opt);
        if (!r) {
          std::fprintf(stderr, "fleetmap: no route from %d to %d on '%s'%s (radius %s m)\n", a, b, map->c_str(),
                       opt->avoid_stairs ? " without stairs" : "", format_number(opt->radius).c_str());
          return exit_code::kNoPath;
        }
        for (size_t i = 0; i < r->nodes.size(); ++i) {
          const Point p = g.node(r->nodes[i]).pos;
          const std::string via = i == 0 ? "-" : std::string(to_string(g.edges()[r->edges[i - 1]].type));
          std::printf("%d %s %s %s\n", r->nodes[i], format_number(p.x).c_str(), format_number(p.y).c_str(),
                      via.c_str());
        }
        std::printf("length %.3f\n", r->length);
        return exit_code::kOk;
      });
    });
  }

  // topo export
  {
    auto map = std::make_shared<std::string>();
    auto format = std::make_shared<std::string>("json");
    auto out = std::make_shared<std::string>();
    auto* cmd = topo->add_subcommand("export", "write a stored graph as navigation JSON or GeoJSON");
    cmd->add_option("MAP", *map, "name of a stored map with a graph")->required();
    cmd->add_option("--format", *format, "json (the import format) or geojson")
        ->check(CLI::IsMember({"json", "geojson"}))
        ->capture_default_str();
    cmd->add_option("-o,--output", *out, "output file (default: standard output)");
    cmd->callback([=, &ctx] {
      guarded(exit_code, [&]() -> int {
        const TopoGraph g = TopoStore(ctx.connection()).load(*map);
        write_output(*format == "json" ? write_topo_json(g) : write_topo_geojson(g, *map), *out);
        return exit_code::kOk;
      });
    });
  }

  // topo delete
  {
    auto map = std::make_shared<std::string>();
    auto* cmd = topo->add_subcommand("delete", "delete the graph of a stored map (the map stays)");
    cmd->add_option("MAP", *map, "map name")->required();
    cmd->callback([=, &ctx] {
      guarded(exit_code, [&]() -> int {
        if (!TopoStore(ctx.connection()).remove(*map)) throw TopoGraphNotFound(*map);
        std::cout << "deleted the graph of '" << *map << "'\n";
        return exit_code::kOk;
      });
    });
  }
}

}  // namespace fleetmap
