#include "server/cli/slice_command.h"

#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>

#include "common/slicing/map_slice.h"
#include "common/slicing/occupancy_grid.h"
#include "common/io/seed_format.h"
#include "app/exit_codes.h"
#include "common/core/error.h"
#include "server/cli/command.h"
#include "server/cli/map_source.h"

namespace fleetmap {
namespace {

bool ends_with(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// OUTPUT, OUTPUT.pgm or OUTPUT.yaml all name the pair OUTPUT.pgm + OUTPUT.yaml.
std::string output_base(const std::string& out) {
  for (const char* ext : {".pgm", ".yaml"})
    if (ends_with(out, ext)) return out.substr(0, out.size() - std::string(ext).size());
  return out;
}

// map slice NAME|--file F --height H [--format seed|pgm] [-o OUTPUT]
struct MapSliceArgs {
  std::string name, file, out, format = "seed";
  double height = 0, resolution = 0.05;
  ObjectSource objects;
};

int run_map_slice(const MapSliceArgs& a, CliContext& ctx) {
  if (a.name.empty() == a.file.empty()) throw BadInput("expected a stored map NAME or --file F (one of them)");
  if (a.format == "pgm" && a.out.empty()) throw BadInput("expected -o OUTPUT with --format pgm");
  // The objects seen at hL join the map as closed polygons as high as their element's
  // top (>= hL), so the slice keeps every one of them (common/slicing/scene_laser.h).
  size_t objects = 0;
  const Map map = load_map_at_height(a.name, a.file, a.objects, a.height, ctx, &objects);
  const Map slice = slice_at_height(map, a.height);
  const std::string what = a.file.empty() ? "'" + a.name + "'" : a.file;
  std::fprintf(stderr, "slice of %s at %g m: %zu of %zu obstacles (%zu of them object elements), %zu of %zu segments\n",
               what.c_str(), a.height, slice.obstacles.size(), map.obstacles.size(), objects, slice.segment_count(),
               map.segment_count());
  if (a.format == "seed") {
    write_output(write_seed(slice), a.out);
  } else {
    const OccupancyGrid grid = rasterize_map(slice, a.resolution);
    const std::string base = output_base(a.out), pgm = base + ".pgm", yaml = base + ".yaml";
    const size_t slash = pgm.find_last_of('/');
    write_output(write_pgm(grid), pgm);
    write_output(write_nav2_yaml(grid, slash == std::string::npos ? pgm : pgm.substr(slash + 1)), yaml);
    std::fprintf(stderr, "occupancy grid %d x %d cells at %g m: %s, %s\n", grid.width, grid.height, a.resolution,
                 pgm.c_str(), yaml.c_str());
  }
  return exit_code::kOk;
}

}  // namespace

void add_slice_command(CLI::App& app, CliContext& ctx) {
  auto a = std::make_shared<MapSliceArgs>();
  // seed 004: the per-robot map, sliced at the robot's laser height.
  auto* cmd = app.get_subcommand("map")->add_subcommand(
      "slice",
      "the map a robot with its laser at --height sees: what stops the laser at that height, the map's "
      "objects included, as a segment map (seed format) or a Nav2 occupancy grid (--format pgm: OUTPUT.pgm + "
      "OUTPUT.yaml for map_server)");
  cmd->add_option("NAME", a->name, "stored map name (or --file)");
  cmd->add_option("--file", a->file, "a map file instead of a stored map (seed format; AMRL if *.vectormap.txt)");
  cmd->add_option("--height", a->height, "laser mounting height hL (m)")->required()->check(CLI::Range(0.0, 1000.0));
  cmd->add_option("--format", a->format, "seed: the sliced segment map (read it back as a window: cut polygons are "
                                         "open); pgm: a Nav2 occupancy grid")
      ->check(CLI::IsMember({"seed", "pgm"}))
      ->capture_default_str();
  cmd->add_option("-o,--output", a->out, "seed: output file (default: standard output); pgm: OUTPUT for OUTPUT.pgm "
                                         "and OUTPUT.yaml (required)");
  cmd->add_option("--resolution", a->resolution, "pgm: metres per cell")->capture_default_str()->check(CLI::PositiveNumber);
  add_object_source_options(*cmd, a->objects);
  run_with(*cmd, a, ctx, run_map_slice);
}

}  // namespace fleetmap
