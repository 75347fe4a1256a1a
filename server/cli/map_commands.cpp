#include "server/cli/map_commands.h"

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>

#include "common/gis/geo_transform.h"
#include "common/io/amrl_import.h"
#include "common/io/map_geojson.h"
#include "common/io/map_svg.h"
#include "common/map/map_validation.h"
#include "common/map/map_window.h"
#include "common/io/seed_format.h"
#include "protocol/fleet_store.h"
#include "protocol/map_store.h"
#include "app/exit_codes.h"
#include "common/core/error.h"
#include "server/cli/command.h"
#include "server/cli/list_json.h"
#include "server/cli/map_source.h"

namespace fleetmap {
namespace {

struct ReadOptions {
  std::string format = "auto";
  AmrlOptions amrl;
};

void add_read_options(CLI::App* cmd, ReadOptions& o) {
  cmd->add_option("--format", o.format, "input format: seed, amrl, or auto (amrl for *.vectormap.txt)")
      ->check(CLI::IsMember({"auto", "seed", "amrl"}))
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
};

int run_map_check(const MapCheckArgs& a, CliContext&) {
  Map m = read_map_file(a.file, a.read);
  std::cout << a.file << ": ok: " << describe_map(m) << "\n";
  return exit_code::kOk;
}

void add_map_check(CLI::App& map, CliContext& ctx) {
  auto a = std::make_shared<MapCheckArgs>();
  auto* cmd = map.add_subcommand("check", "validate a map file without touching the database");
  cmd->add_option("FILE", a->file, "map file")->required();
  add_read_options(cmd, a->read);
  run_with(*cmd, a, ctx, run_map_check);
}

// map import FILE --name NAME: one transaction.
struct MapImportArgs {
  std::string file, name;
  bool replace = false;
  ReadOptions read;
};

int run_map_import(const MapImportArgs& a, CliContext& ctx) {
  if (auto e = check_map_name(a.name)) throw BadInput(*e);
  Map m = read_map_file(a.file, a.read);
  const auto t0 = std::chrono::steady_clock::now();
  MapStore store(ctx.connection());
  store.import(m, a.name, a.file, a.replace, progress_printer());
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("imported '%s': %zu obstacles, %zu segments in %.2f s (%.0f segments/s)\n", a.name.c_str(),
              m.obstacles.size(), m.segment_count(), s, m.segment_count() / std::max(s, 1e-9));
  return exit_code::kOk;
}

void add_map_import(CLI::App& map, CliContext& ctx) {
  auto a = std::make_shared<MapImportArgs>();
  auto* cmd = map.add_subcommand("import", "import a map file (one transaction: all or nothing)");
  cmd->add_option("FILE", a->file, "map file")->required();
  cmd->add_option("--name", a->name, "map name, [A-Za-z0-9_.-]{1,64}")->required();
  cmd->add_flag("--replace", a->replace, "replace a map of the same name");
  add_read_options(cmd, a->read);
  run_with(*cmd, a, ctx, run_map_import);
}

// map export NAME: seed text, GeoJSON or SVG (with the robots' trajectories).
struct MapExportArgs {
  std::string name, format = "seed", out, since;
  bool trajectories = false;
};

int run_map_export(const MapExportArgs& a, CliContext& ctx) {
  MapStore store(ctx.connection());
  const Map m = store.load(a.name);
  std::string text;
  if (a.format == "seed") text = write_seed(m);
  else if (a.format == "geojson") text = write_geojson(m, a.name);
  else {
    SvgOptions so;
    so.title = a.name;
    if (a.trajectories) {
      FleetStore fleet(ctx.connection());
      for (const RobotStatus& r : fleet.status()) {
        if (r.map != a.name) continue;
        SvgTrack t;
        t.label = r.name;
        std::optional<std::string> from;
        if (!a.since.empty()) from = a.since;
        for (const TrajectoryPoint& p : fleet.trajectory(r.name, from)) t.points.push_back({p.x, p.y});
        if (!t.points.empty()) so.tracks.push_back(std::move(t));
      }
    }
    text = write_svg(m, so);
  }
  write_output(text, a.out);
  return exit_code::kOk;
}

void add_map_export(CLI::App& map, CliContext& ctx) {
  auto a = std::make_shared<MapExportArgs>();
  auto* cmd = map.add_subcommand("export", "write a stored map as seed text, GeoJSON or SVG");
  cmd->add_flag("--trajectories", a->trajectories, "svg: draw the trajectories of the map's robots");
  cmd->add_option("--since", a->since, "with --trajectories: only poses since this timestamp or age (10m, 2h)")
      ->type_name("TIME|AGE");
  cmd->add_option("NAME", a->name, "map name")->required();
  cmd->add_option("--format", a->format, "seed, geojson or svg")
      ->check(CLI::IsMember({"seed", "geojson", "svg"}))
      ->capture_default_str();
  cmd->add_option("-o,--output", a->out, "output file (default: standard output)");
  run_with(*cmd, a, ctx, run_map_export);
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
  std::printf("deleted '%s'\n", a.name.c_str());
  return exit_code::kOk;
}

void add_map_delete(CLI::App& map, CliContext& ctx) {
  auto a = std::make_shared<MapDeleteArgs>();
  auto* cmd = map.add_subcommand("delete", "delete a stored map");
  cmd->add_option("NAME", a->name, "map name")->required();
  run_with(*cmd, a, ctx, run_map_delete);
}

// map georef NAME LAT LON [--heading H] | --clear
struct MapGeorefArgs {
  std::string name;
  std::optional<double> lat, lon;
  double heading = 0;
  bool clear = false;
};

int run_map_georef(const MapGeorefArgs& a, CliContext& ctx) {
  MapStore store(ctx.connection());
  if (a.clear) {
    store.set_georef(a.name, std::nullopt);
  } else {
    if (!a.lat || !a.lon) throw BadInput("expected LAT and LON, or --clear");
    if (!std::isfinite(a.heading)) throw BadInput("expected a finite --heading");
    const MapGeoref g = georef_from_origin(*a.lat, *a.lon, a.heading);
    GeoTransform check(g);  // throws BadInput when PROJ cannot use it
    store.set_georef(a.name, g);
  }
  std::printf("map '%s' %s\n", a.name.c_str(), a.clear ? "is no longer georeferenced" : "georeferenced");
  return exit_code::kOk;
}

void add_map_georef(CLI::App& map, CliContext& ctx) {
  auto a = std::make_shared<MapGeorefArgs>();
  auto* cmd = map.add_subcommand("georef", "georeference a map: SendGPS fixes then get map coordinates");
  cmd->add_option("NAME", a->name, "map name")->required();
  cmd->add_option("LAT", a->lat, "latitude of the map origin (degrees, WGS84)")->check(CLI::Range(-90.0, 90.0));
  cmd->add_option("LON", a->lon, "longitude of the map origin (degrees)")->check(CLI::Range(-180.0, 180.0));
  cmd->add_option("--heading", a->heading, "direction of the map x axis, radians counter-clockwise from east")
      ->capture_default_str();
  cmd->add_flag("--clear", a->clear, "remove the georeference");
  run_with(*cmd, a, ctx, run_map_georef);
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
