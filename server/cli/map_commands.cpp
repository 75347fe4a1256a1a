#include "server/cli/map_commands.h"

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>

#include "common/io/amrl_import.h"
#include "common/io/map_geojson.h"
#include "common/io/map_svg.h"
#include "common/map/map_validation.h"
#include "common/map/map_window.h"
#include "common/io/seed_format.h"
#include "protocol/fleet_store.h"
#include "protocol/map_store.h"
#include "app/exit_codes.h"
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

}  // namespace

void add_map_commands(CLI::App& app, CliContext& ctx, int* exit_code) {
  auto* map = app.add_subcommand("map", "import, export, list, check and delete maps");
  map->require_subcommand(1);

  // map check
  {
    auto o = std::make_shared<ReadOptions>();
    auto file = std::make_shared<std::string>();
    auto* cmd = map->add_subcommand("check", "validate a map file without touching the database");
    cmd->add_option("FILE", *file, "map file")->required();
    add_read_options(cmd, *o);
    cmd->callback([=] {
      Map m = read_map_file(*file, *o);
      std::cout << *file << ": ok: " << describe_map(m) << "\n";
      *exit_code = exit_code::kOk;
    });
  }

  // map import
  {
    auto o = std::make_shared<ReadOptions>();
    auto file = std::make_shared<std::string>();
    auto name = std::make_shared<std::string>();
    auto replace = std::make_shared<bool>(false);
    auto* cmd = map->add_subcommand("import", "import a map file (one transaction: all or nothing)");
    cmd->add_option("FILE", *file, "map file")->required();
    cmd->add_option("--name", *name, "map name, [A-Za-z0-9_.-]{1,64}")->required();
    cmd->add_flag("--replace", *replace, "replace a map of the same name");
    add_read_options(cmd, *o);
    cmd->callback([=, &ctx] {
      if (auto e = check_map_name(*name)) throw std::invalid_argument(*e);
      Map m = read_map_file(*file, *o);
      const auto t0 = std::chrono::steady_clock::now();
      MapStore store(ctx.connection());
      store.import(m, *name, *file, *replace, progress_printer());
      const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      std::printf("imported '%s': %zu obstacles, %zu segments in %.2f s (%.0f segments/s)\n", name->c_str(),
                  m.obstacles.size(), m.segment_count(), s, m.segment_count() / std::max(s, 1e-9));
      *exit_code = exit_code::kOk;
    });
  }

  // map export
  {
    auto name = std::make_shared<std::string>();
    auto format = std::make_shared<std::string>("seed");
    auto out = std::make_shared<std::string>();
    auto tracks = std::make_shared<bool>(false);
    auto* cmd = map->add_subcommand("export", "write a stored map as seed text, GeoJSON or SVG");
    cmd->add_flag("--trajectories", *tracks, "svg: draw the trajectories of the map's robots");
    auto since = std::make_shared<std::string>();
    cmd->add_option("--since", *since, "with --trajectories: only poses since this timestamp or age (10m, 2h)");
    cmd->add_option("NAME", *name, "map name")->required();
    cmd->add_option("--format", *format, "seed, geojson or svg")
        ->check(CLI::IsMember({"seed", "geojson", "svg"}))
        ->capture_default_str();
    cmd->add_option("-o,--output", *out, "output file (default: standard output)");
    cmd->callback([=, &ctx] {
      MapStore store(ctx.connection());
      const Map m = store.load(*name);
      std::string text;
      if (*format == "seed") text = write_seed(m);
      else if (*format == "geojson") text = write_geojson(m, *name);
      else {
        SvgOptions so;
        so.title = *name;
        if (*tracks) {
          FleetStore fleet(ctx.connection());
          for (const RobotStatus& r : fleet.status()) {
            if (r.map != *name) continue;
            SvgTrack t;
            t.label = r.name;
            std::optional<std::string> from;
            if (!since->empty()) from = *since;
            for (const TrajectoryPoint& p : fleet.trajectory(r.name, from)) t.points.push_back({p.x, p.y});
            if (!t.points.empty()) so.tracks.push_back(std::move(t));
          }
        }
        text = write_svg(m, so);
      }
      write_output(text, *out);
      *exit_code = exit_code::kOk;
    });
  }

  // map list
  {
    auto* cmd = map->add_subcommand("list", "list stored maps");
    cmd->callback([=, &ctx] {
      MapStore store(ctx.connection());
      std::printf("%-24s %9s %9s  %-44s %s\n", "NAME", "OBSTACLES", "SEGMENTS", "BORDER (mx1,my1)-(mx4,my4)", "IMPORTED");
      for (const MapInfo& i : store.list()) {
        char border[96];
        std::snprintf(border, sizeof border, "(%.2f,%.2f)-(%.2f,%.2f)", i.border.mx1, i.border.my1, i.border.mx4,
                      i.border.my4);
        std::printf("%-24s %9zu %9zu  %-44s %s\n", i.name.c_str(), i.obstacles, i.segments, border,
                    i.imported_at.c_str());
      }
      *exit_code = exit_code::kOk;
    });
  }

  // map delete
  {
    auto name = std::make_shared<std::string>();
    auto* cmd = map->add_subcommand("delete", "delete a stored map");
    cmd->add_option("NAME", *name, "map name")->required();
    cmd->callback([=, &ctx] {
      MapStore store(ctx.connection());
      if (!store.remove(*name)) throw MapNotFound(*name);
      std::printf("deleted '%s'\n", name->c_str());
      *exit_code = exit_code::kOk;
    });
  }

  // map georef
  {
    auto name = std::make_shared<std::string>();
    auto lat = std::make_shared<double>(), lon = std::make_shared<double>();
    auto heading = std::make_shared<double>(0);
    auto clear = std::make_shared<bool>(false);
    auto* cmd = map->add_subcommand("georef", "georeference a map: SendGPS fixes then get map coordinates");
    cmd->add_option("NAME", *name, "map name")->required();
    cmd->add_option("LAT", *lat, "latitude of the map origin (degrees, WGS84)")->check(CLI::Range(-90.0, 90.0));
    cmd->add_option("LON", *lon, "longitude of the map origin (degrees)")->check(CLI::Range(-180.0, 180.0));
    cmd->add_option("--heading", *heading, "direction of the map x axis, radians counter-clockwise from east")
        ->capture_default_str();
    cmd->add_flag("--clear", *clear, "remove the georeference");
    cmd->callback([=, &ctx] {
      MapStore store(ctx.connection());
      if (*clear) {
        store.set_georef(*name, std::nullopt, std::nullopt, 0);
      } else {
        if (cmd->count("LAT") == 0 || cmd->count("LON") == 0) throw std::invalid_argument("expected LAT and LON, or --clear");
        if (!std::isfinite(*heading)) throw std::invalid_argument("expected a finite --heading");
        store.set_georef(*name, *lat, *lon, *heading);
      }
      std::printf("map '%s' %s\n", name->c_str(), *clear ? "is no longer georeferenced" : "georeferenced");
      *exit_code = exit_code::kOk;
    });
  }

  // window
  {
    auto name = std::make_shared<std::string>();
    auto v = std::make_shared<std::array<double, 4>>();
    auto out = std::make_shared<std::string>();
    auto* cmd = app.add_subcommand(
        "window", "print the partial map of the W (along x) x H (along y) window centred on (X, Y), seed format");
    cmd->add_option("NAME", *name, "map name")->required();
    cmd->add_option("X", (*v)[0], "window centre x (m)")->required();
    cmd->add_option("Y", (*v)[1], "window centre y (m)")->required();
    cmd->add_option("W", (*v)[2], "window width along x (m), > 0")->required();
    cmd->add_option("H", (*v)[3], "window height along y (m), > 0")->required();
    cmd->add_option("-o,--output", *out, "output file (default: standard output)");
    cmd->callback([=, &ctx] {
      const auto [x, y, w, h] = *v;
      for (double d : *v)
        if (!std::isfinite(d)) throw std::invalid_argument("expected finite numbers for X Y W H");
      if (!(w > 0 && h > 0)) throw std::invalid_argument("expected W > 0 and H > 0");
      MapStore store(ctx.connection());
      const MapInfo info = store.info(*name);
      const Rect r = window_rect(info.border, {x, y}, w, h);
      if (r.empty()) throw std::invalid_argument("expected a window that overlaps the map's border, got one outside it");
      const Map part = store.window(*name, r);
      write_output(write_seed(part), *out);
      *exit_code = exit_code::kOk;
    });
  }
}

}  // namespace fleetmap
