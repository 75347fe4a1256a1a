#include "server/cli/plan_command.h"

#include "common/geometry/number_format.h"
#include "server/cli/map_source.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "common/io/amrl_import.h"
#include "common/planning/map_planner.h"
#include "common/io/map_svg.h"
#include "common/planning/planning_scene.h"
#include "common/io/seed_format.h"
#include "protocol/map_store.h"
#include "app/exit_codes.h"
#include "common/core/error.h"
#include "server/cli/command.h"

namespace fleetmap {
namespace {

struct PlanArgs {
  std::vector<std::string> positional;  // [MAP] X1 Y1 X2 Y2
  std::string file, svg;
  PlannerOptions planner;
  double body_height = 1.0;  // the server's default body_height_m
  ObjectSource objects;      // the stored map's scene, or --objects F with --file
};

double parse_coordinate(const std::string& text, const char* name) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !std::isfinite(v))
    throw BadInput(std::string("expected a finite number for ") + name + ", got '" + text + "'");
  return v;
}

Map load_map(const PlanArgs& a, CliContext& ctx, std::string* name) {
  *name = a.file.empty() ? a.positional[0] : a.file;
  return load_map_source(a.file.empty() ? a.positional[0] : "", a.file, ctx);
}

// Why an object blocks: it starts below the body's top (see --body-height).
std::string body_note(const std::string& name, const PlanArgs& a) {
  if (name.rfind("object:", 0) != 0) return "";
  return ", which a body " + format_number(a.body_height) + " m tall cannot pass (see --body-height)";
}

std::string describe(Point p) {
  char buf[80];
  std::snprintf(buf, sizeof buf, "(%.3f, %.3f)", p.x, p.y);
  return buf;
}

// "start (1, 2) is blocked: ..." for the status of a blocked end.
std::string blocked_message(const char* which, Point p, const Collision& c, const PlanArgs& a,
                            const PlanningObstacles& obstacles) {
  std::string s = std::string(which) + " " + describe(p) + " is blocked: ";
  char r[32];
  std::snprintf(r, sizeof r, "%g m", a.planner.radius);
  const auto named = obstacles.names.find(c.obstacle_id);
  switch (c.kind) {
    case Collision::Kind::Border:
      return s + "a robot of radius " + r + " centred there does not fit inside the map's border";
    case Collision::Kind::Area:
      if (named != obstacles.names.end()) return s + "it is inside " + named->second + body_note(named->second, a);
      return s + "it is on the stairs of obstacle " + std::to_string(c.obstacle_id) +
             ", which a wheeled robot may not enter (see --climb-stairs)";
    case Collision::Kind::Segment:
      break;
  }
  if (named != obstacles.names.end())
    return s + "it is within the robot radius " + r + " of " + named->second + body_note(named->second, a);
  return s + "it is within the robot radius " + r + " of obstacle " + std::to_string(c.obstacle_id);
}

void write_svg_file(const Map& m, const std::string& title, const Path& path, const std::string& file) {
  SvgOptions so;
  so.title = title;
  so.tracks.push_back({"planned path", "#d62728", path});
  std::ofstream out(file, std::ios::binary);
  out << write_svg(m, so);
  if (!out) throw IoError("cannot write '" + file + "'");
}

int run_plan(const PlanArgs& a, CliContext& ctx) {
  const size_t want = a.file.empty() ? 5 : 4;
  if (a.positional.size() != want)
    throw CLI::ValidationError(a.file.empty() ? "expected MAP X1 Y1 X2 Y2 (or --file F X1 Y1 X2 Y2)"
                                              : "expected X1 Y1 X2 Y2 after --file F, without MAP");
  const size_t k = want - 4;
  const Point start{parse_coordinate(a.positional[k], "X1"), parse_coordinate(a.positional[k + 1], "Y1")};
  const Point goal{parse_coordinate(a.positional[k + 2], "X2"), parse_coordinate(a.positional[k + 3], "Y2")};
  std::string name;
  const Scene scene = load_scene_source(a.file.empty() ? a.positional[0] : "", a.file, a.objects, ctx);
  const Map map = load_map(a, ctx, &name);

  const MapPlanner planner(map, planning_obstacles(map, scene, a.body_height, a.planner.robot), a.planner);
  const PlanningObstacles& obstacles = planner.checker().obstacles();
  const PlanResult r = planner.plan(start, goal);
  switch (r.status) {
    case PlanStatus::StartBlocked:
      std::cerr << "fleetmap plan: " << blocked_message("start", start, *r.collision, a, obstacles) << "\n";
      return exit_code::kNoPath;
    case PlanStatus::GoalBlocked:
      std::cerr << "fleetmap plan: " << blocked_message("goal", goal, *r.collision, a, obstacles) << "\n";
      return exit_code::kNoPath;
    case PlanStatus::NoPath:
      std::fprintf(stderr,
                   "fleetmap plan: no path found from %s to %s on '%s' for a robot of radius %g m: RRT-Connect's trees did "
                   "not meet in %zu iterations (%.2f s%s)\n",
                   describe(start).c_str(), describe(goal).c_str(), name.c_str(), a.planner.radius, r.rrt.iterations,
                   r.rrt.seconds, r.rrt.timed_out ? ", time limit reached; try a larger --max-time" : "");
      return exit_code::kNoPath;
    case PlanStatus::Found:
      break;
  }
  for (const Point& p : *r.path) std::printf("%.3f %.3f\n", p.x, p.y);
  std::printf("length %.3f\n", r.length);
  std::fprintf(stderr,
               "planned in %.1f ms: RRT-Connect %zu iterations, raw path %.3f m; smoothed %zu waypoints, %zu of %zu "
               "corners rounded\n",
               1e3 * r.seconds, r.rrt.iterations, path_length(r.raw), r.path->size(), r.smoothing.rounded,
               r.smoothing.corners);
  if (!a.svg.empty()) write_svg_file(map, name + ": " + describe(start) + " to " + describe(goal), *r.path, a.svg);
  return exit_code::kOk;
}

void add_plan(CLI::App& app, CliContext& ctx) {
  auto a = std::make_shared<PlanArgs>();
  a->planner.rrt.max_time = 5;
  // SPEC 7: the planner GetPath uses, on a stored map or a file.
  auto* cmd = app.add_subcommand("plan", "plan a path for a disc robot: RRT-Connect, then smoothing");
  cmd->add_option("ARGS", a->positional, "MAP X1 Y1 X2 Y2: stored map name, start and goal (m); no MAP with --file")
      ->type_name("[MAP] FLOAT")
      ->expected(4, 5)
      ->required();
  cmd->add_option("--file", a->file, "plan on a map file instead of a stored map (seed format; AMRL if *.vectormap.txt)");
  cmd->add_option("--radius", a->planner.radius, "robot radius (m)")->check(CLI::Range(0.0, 100.0))->capture_default_str();
  cmd->add_option("--seed", a->planner.seed, "random seed (same seed, same path)")->capture_default_str();
  cmd->add_option("--body-height", a->body_height, "the robot's height (m): objects starting below it block")
      ->check(CLI::Range(0.0, 1000.0))
      ->capture_default_str();
  add_object_source_options(*cmd, a->objects);
  cmd->add_flag("--climb-stairs", a->planner.robot.can_climb_stairs, "the robot climbs stairs (default: wheeled)");
  cmd->add_option("--attempts", a->planner.attempts, "RRT-Connect runs, the shortest kept")
      ->check(CLI::Range(1, 1000))
      ->capture_default_str();
  cmd->add_option("--max-time", a->planner.rrt.max_time, "time limit of the search (s), 0 none")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  cmd->add_option("--svg", a->svg, "also draw the map and the path into this SVG file");
  cmd->footer(
      "The map's objects whose height range starts below --body-height block, and so does every avoided area "
      "(docs/semantic-layer.md, 'Planning with objects'). "
      "Prints one 'x y' waypoint a line, then 'length L'. Exit codes: 0 path found, 1 failure (database, I/O: "
      "a map file that cannot be read), 2 malformed input, "
      "3 no path (start or goal blocked, or none found within the limits), 4 no such map, 64 usage.");
  run_with(*cmd, a, ctx, run_plan);
}

}  // namespace

void add_plan_command(CLI::App& app, CliContext& ctx) { add_plan(app, ctx); }

}  // namespace fleetmap
