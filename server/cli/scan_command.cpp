#include "server/cli/scan_command.h"

#include <cmath>
#include <cstdio>
#include <memory>

#include "app/exit_codes.h"
#include "common/core/error.h"
#include "common/raycast/ray_caster.h"
#include "common/raycast/seed_ray_caster.h"
#include "common/raycast/sweep_ray_caster.h"
#include "server/cli/command.h"
#include "server/cli/map_source.h"

namespace fleetmap {
namespace {

// scan [MAP] X Y THETA [--file F]: one 'angle range' line per beam.
struct ScanArgs {
  std::vector<std::string> positional;  // [MAP] X Y THETA
  std::string file, method = "fast";
  double height = 0.3, fov = 180, rmax = 15;
  int beams = 131;
  ObjectSource objects;
};

int run_scan(const ScanArgs& a, CliContext& ctx) {
  const size_t want = a.file.empty() ? 4 : 3;
  if (a.positional.size() != want)
    throw BadInput(a.file.empty() ? "expected MAP X Y THETA (or --file F X Y THETA)"
                                  : "expected X Y THETA after --file F, without MAP");
  double v[3];
  for (int i = 0; i < 3; ++i) {
    const std::string& t = a.positional[want - 3 + i];
    char* end = nullptr;
    v[i] = std::strtod(t.c_str(), &end);
    if (t.empty() || *end != '\0' || !std::isfinite(v[i]))
      throw BadInput("expected a finite number for " + std::string(i == 0 ? "X" : i == 1 ? "Y" : "THETA") + ", got '" +
                     t + "'");
  }
  // The objects seen at the laser's height stop its beams like the walls
  // (common/slicing/scene_laser.h).
  const Map map = load_map_at_height(a.file.empty() ? a.positional[0] : "", a.file, a.objects, a.height, ctx);
  const RayCasterOptions o{a.height, a.rmax};
  std::unique_ptr<RayCaster> caster;
  if (a.method == "seed") caster = std::make_unique<SeedRayCaster>(map, o);
  else caster = make_fast_ray_caster(map, o);
  const std::vector<double> rel = evenly_spread_angles(a.beams, a.fov * M_PI / 180);
  std::vector<double> ranges(rel.size());
  caster->cast_scan({v[0], v[1]}, v[2], rel, ranges.data());
  for (size_t i = 0; i < rel.size(); ++i) std::printf("%.6f %.6f\n", v[2] + rel[i], ranges[i]);
  return exit_code::kOk;
}

}  // namespace

void add_scan_command(CLI::App& app, CliContext& ctx) {
  auto a = std::make_shared<ScanArgs>();
  auto* cmd = app.add_subcommand("scan", "what a laser sees from a pose, the map's objects included: one 'angle range' "
                                         "line per beam (radians, map frame; beams evenly from THETA-FOV/2 to "
                                         "THETA+FOV/2; no hit -> RMAX)");
  cmd->add_option("ARGS", a->positional, "MAP X Y THETA (m, m, rad); no MAP with --file")
      ->type_name("[MAP] FLOAT")
      ->required()
      ->expected(3, 4);
  cmd->add_option("--file", a->file, "a map file instead of a stored map (seed format; AMRL if *.vectormap.txt)");
  cmd->add_option("--height", a->height, "laser mounting height hL (m)")->capture_default_str()->check(CLI::Range(0.0, 1000.0));
  cmd->add_option("--beams", a->beams, "number of beams NL")->capture_default_str()->check(CLI::Range(1, 100000));
  cmd->add_option("--fov", a->fov, "field of view (degrees)")->capture_default_str()->check(CLI::Range(0.0, 360.0));
  cmd->add_option("--rmax", a->rmax, "maximum range RMAX (m)")->capture_default_str()->check(CLI::Range(0.001, 1e6));
  add_object_source_options(*cmd, a->objects);
  cmd->add_option("--method", a->method, "seed (bounding circles, the reference) or fast")
      ->check(CLI::IsMember({"seed", "fast"}))
      ->capture_default_str();
  run_with(*cmd, a, ctx, run_scan);
}

}  // namespace fleetmap
