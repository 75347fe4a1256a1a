#include "server/cli/map_commands.h"

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <iterator>
#include <map>
#include <string>
#include <vector>

#include "common/gis/geo_transform.h"
#include "common/io/amrl_import.h"
#include "common/map/map_validation.h"
#include "common/map/map_window.h"
#include "common/io/seed_format.h"
#include "protocol/fleet_store.h"
#include "protocol/map_store.h"
#include "app/exit_codes.h"
#include "common/core/error.h"
#include "server/cli/command.h"
#include "server/cli/georef_command.h"
#include "server/cli/map_export_command.h"
#include "server/cli/gis_publish.h"
#include "server/cli/gis_import.h"
#include "server/cli/list_json.h"
#include "server/cli/map_source.h"

namespace fleetmap {
namespace {

struct ReadOptions {
  std::string format = "auto";
  AmrlOptions amrl;
};

void add_read_options(CLI::App* cmd, ReadOptions& o) {
  cmd->add_option("--format", o.format, "input format: seed, amrl, ogr (GIS, through GDAL/OGR), or auto (by the name)")
      ->check(CLI::IsMember({"auto", "seed", "amrl", "ogr"}))
      ->capture_default_str();
  cmd->add_option("--height", o.amrl.height, "amrl: height of every wall (m)")->capture_default_str();
  cmd->add_option("--in-out", o.amrl.in_out, "amrl: 0 indoor, 1 outdoor")->check(CLI::IsMember({0, 1}))->capture_default_str();
  cmd->add_option("--semantic", o.amrl.semantic, "amrl: semantic string of every wall")->capture_default_str();
  cmd->add_option("--margin", o.amrl.margin, "amrl: border margin around the walls (m)")->capture_default_str();
}

bool is_amrl(const ReadOptions& o, const std::string& file) {
  if (o.format != "auto") return o.format == "amrl";
  return is_amrl_file(file);
}

// Reads and validates a map file; prints what the AMRL importer skipped.
Map read_map_file(const std::string& file, const ReadOptions& o) {
  if (!is_amrl(o, file)) return read_seed_file(file);
  AmrlReport rep;
  Map m = read_amrl_file(file, o.amrl, &rep);
  std::cerr << file << ": " << rep.lines << " lines, " << rep.segments << " segments kept, "
            << rep.zero_length_skipped << " zero-length lines skipped, " << rep.obstacles << " obstacles ("
            << rep.closed << " closed)\n";
  return m;
}

std::string describe_map(const Map& m) {
  std::map<int, size_t> by_type;
  for (const Obstacle& o : m.obstacles) ++by_type[static_cast<int>(o.type)];
  std::string s = std::to_string(m.obstacles.size()) + " obstacles, " + std::to_string(m.segment_count()) +
                  " segments, border (" + std::to_string(m.border.mx1) + ", " + std::to_string(m.border.my1) +
                  ") to (" + std::to_string(m.border.mx4) + ", " + std::to_string(m.border.my4) + ")";
  for (auto [t, c] : by_type)
    s += "\n  ST " + std::to_string(t) + " " + std::string(to_string(static_cast<ShapeType>(t))) + ": " +
         std::to_string(c);
  return s;
}


// Import progress on stderr: a live line on a terminal, every 10 % otherwise.
ImportProgress progress_printer() {
  const bool tty = isatty(fileno(stderr));
  auto last = std::make_shared<int>(-1);
  return [tty, last](size_t done, size_t total) {
    const int pct = total ? static_cast<int>(100 * done / total) : 100;
    if (tty) {
      std::fprintf(stderr, "\rimporting: %zu/%zu segments (%d%%)%s", done, total, pct, done == total ? "\n" : "");
    } else if (pct / 10 != *last / 10 || done == total) {
      std::fprintf(stderr, "importing: %zu/%zu segments (%d%%)\n", done, total, pct);
    }
    *last = pct;
  };
}

// map check FILE: read and validate, no database.
struct MapCheckArgs {
  std::string file;
  ReadOptions read;
  GisImportOptions gis;
};

int run_map_check(const MapCheckArgs& a, CliContext& ctx) {
  if (use_ogr(a.file, a.read.format)) return run_gis_check(a.file, a.gis, ctx);
  Map m = read_map_file(a.file, a.read);
  std::cout << a.file << ": ok: " << describe_map(m) << "\n";
  return exit_code::kOk;
}

void add_map_check(CLI::App& map, CliContext& ctx) {
  auto a = std::make_shared<MapCheckArgs>();
  auto* cmd = map.add_subcommand("check", "validate a map file without touching the database");
  cmd->add_option("FILE", a->file, "map file")->required();
  add_read_options(cmd, a->read);
  add_gis_options(cmd, a->gis);
  run_with(*cmd, a, ctx, run_map_check);
}

// map import FILE --name NAME [--replace [--drop WHAT,...] [--force]]: one transaction.
struct MapImportArgs {
  std::string file, name;
  bool replace = false, force = false;
  std::vector<std::string> drop;
  ReadOptions read;
  GisImportOptions gis;
};

// What a replace kept, dropped and stranded (protocol/map_replace.h).
void print_replace_report(const MapReplaceReport& r) {
  auto line = [](const char* label, const std::vector<std::string>& items) {
    std::string s;
    for (const std::string& i : items) s += (s.empty() ? "" : ", ") + i;
    std::printf("  %s: %s\n", label, s.empty() ? "nothing" : s.c_str());
  };
  std::vector<std::string> kept = describe(r.kept);
  if (r.georef_replaced) kept.push_back("the import's own georeference");
  line("kept", kept);
  line("dropped", describe(r.dropped));
  if (!r.stranded.empty()) {
    std::printf("  stranded (kept, --force): %zu\n", r.stranded.size());
    for (const StrandedDependent& d : r.stranded) std::printf("    %s\n", d.text().c_str());
  }
}

int run_map_import(const MapImportArgs& a, CliContext& ctx) {
  if (auto e = check_map_name(a.name)) throw BadInput(*e);
  MapImportOptions options;
  options.replace = a.replace;
  options.drop = parse_map_drop(a.drop);
  options.force = a.force;
  options.progress = progress_printer();
  if (use_ogr(a.file, a.read.format)) {
    const MapImportReport r = run_gis_import(a.file, a.name, options, a.gis, ctx);
    if (r.replaced) print_replace_report(r.replace);
    publish_gis_layers(ctx.connection(), a.name);
    return exit_code::kOk;
  }
  Map m = read_map_file(a.file, a.read);
  const auto t0 = std::chrono::steady_clock::now();
  MapStore store(ctx.connection());
  const MapImportReport r = store.import(m, a.name, a.file, options);
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("%s '%s': %zu obstacles, %zu segments in %.2f s (%.0f segments/s)\n",
              r.replaced ? "replaced" : "imported", a.name.c_str(), m.obstacles.size(), m.segment_count(), s,
              m.segment_count() / std::max(s, 1e-9));
  if (r.replaced) print_replace_report(r.replace);
  publish_gis_layers(ctx.connection(), a.name);
  return exit_code::kOk;
}

void add_map_import(CLI::App& map, CliContext& ctx) {
  auto a = std::make_shared<MapImportArgs>();
  auto* cmd = map.add_subcommand("import", "import a map file (one transaction: all or nothing)");
  cmd->add_option("FILE", a->file, "map file")->required();
  cmd->add_option("--name", a->name, "map name, [A-Za-z0-9_.-]{1,64}")->required();
  auto* replace = cmd->add_flag("--replace", a->replace,
                                "replace a map of the same name: it keeps its id, robots, objects, avoided areas, "
                                "bounds, topology and georeference");
  cmd->add_option("--drop", a->drop,
                  "with --replace: delete these with the old map (objects, areas, bounds, topology, georef, all)")
      ->delimiter(',')
      ->check(CLI::IsMember(std::vector<std::string>(std::begin(kMapDropWords), std::end(kMapDropWords))))
      ->type_name("WHAT,...")
      ->needs(replace);
  cmd->add_flag("--force", a->force,
                "with --replace: replace even when robots, goals, objects, areas, bounds or topology nodes would be "
                "left outside the new border or inside a new closed obstacle")
      ->needs(replace);
  add_read_options(cmd, a->read);
  add_gis_options(cmd, a->gis);
  run_with(*cmd, a, ctx, run_map_import);
}

// map list
struct MapListArgs {
  bool json = false;
};

int run_map_list(const MapListArgs& a, CliContext& ctx) {
  MapStore store(ctx.connection());
  if (a.json) {
    std::printf("%s\n", maps_json(store.list()).dump().c_str());
    return exit_code::kOk;
  }
  std::printf("%-24s %9s %9s  %-44s %s\n", "NAME", "OBSTACLES", "SEGMENTS", "BORDER (mx1,my1)-(mx4,my4)", "IMPORTED");
  for (const MapInfo& i : store.list()) {
    char border[96];
    std::snprintf(border, sizeof border, "(%.2f,%.2f)-(%.2f,%.2f)", i.border.mx1, i.border.my1, i.border.mx4,
                  i.border.my4);
    std::printf("%-24s %9zu %9zu  %-44s %s\n", i.name.c_str(), i.obstacles, i.segments, border, i.imported_at.c_str());
  }
  return exit_code::kOk;
}

void add_map_list(CLI::App& map, CliContext& ctx) {
  auto a = std::make_shared<MapListArgs>();
  auto* cmd = map.add_subcommand("list", "list stored maps");
  cmd->add_flag("--json", a->json, "a JSON array, one object per map (server/cli/list_json.h)");
  run_with(*cmd, a, ctx, run_map_list);
}

// map delete NAME
struct MapDeleteArgs {
  std::string name;
};

int run_map_delete(const MapDeleteArgs& a, CliContext& ctx) {
  MapStore store(ctx.connection());
  if (!store.remove(a.name)) throw MapNotFound(a.name);
  withdraw_gis_layers(ctx.connection());
  std::printf("deleted '%s'\n", a.name.c_str());
  return exit_code::kOk;
}

void add_map_delete(CLI::App& map, CliContext& ctx) {
  auto a = std::make_shared<MapDeleteArgs>();
  auto* cmd = map.add_subcommand("delete", "delete a stored map");
  cmd->add_option("NAME", a->name, "map name")->required();
  run_with(*cmd, a, ctx, run_map_delete);
}

// window NAME X Y W H: the partial map, seed format.
struct WindowArgs {
  std::string name, out;
  double x = 0, y = 0, w = 0, h = 0;
};

int run_window(const WindowArgs& a, CliContext& ctx) {
  for (double d : {a.x, a.y, a.w, a.h})
    if (!std::isfinite(d)) throw BadInput("expected finite numbers for X Y W H");
  if (!(a.w > 0 && a.h > 0)) throw BadInput("expected W > 0 and H > 0");
  MapStore store(ctx.connection());
  const MapInfo info = store.info(a.name);
  const Rect r = window_rect(info.border, {a.x, a.y}, a.w, a.h);
  if (r.empty()) throw BadInput("expected a window that overlaps the map's border, got one outside it");
  const Map part = store.window(a.name, r);
  write_output(write_seed(part), a.out);
  return exit_code::kOk;
}

void add_window(CLI::App& app, CliContext& ctx) {
  auto a = std::make_shared<WindowArgs>();
  auto* cmd = app.add_subcommand(
      "window", "print the partial map of the W (along x) x H (along y) window centred on (X, Y), seed format");
  cmd->add_option("NAME", a->name, "map name")->required();
  cmd->add_option("X", a->x, "window centre x (m)")->required();
  cmd->add_option("Y", a->y, "window centre y (m)")->required();
  cmd->add_option("W", a->w, "window width along x (m), > 0")->required();
  cmd->add_option("H", a->h, "window height along y (m), > 0")->required();
  cmd->add_option("-o,--output", a->out, "output file (default: standard output)");
  run_with(*cmd, a, ctx, run_window);
}

}  // namespace

void add_map_commands(CLI::App& app, CliContext& ctx) {
  auto* map = app.add_subcommand("map", "import, export, list, check and delete maps");
  map->require_subcommand(1);
  add_map_check(*map, ctx);
  add_map_import(*map, ctx);
  add_map_export(*map, ctx);
  add_map_list(*map, ctx);
  add_map_delete(*map, ctx);
  add_map_georef(*map, ctx);
  add_window(app, ctx);
}

}  // namespace fleetmap
