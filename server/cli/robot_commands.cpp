#include "server/cli/robot_commands.h"

#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <iostream>
#include <map>
#include <random>
#include <regex>
#include <sstream>
#include <thread>

#include <nlohmann/json.hpp>

#include "common/io/trajectory_geojson.h"
#include "protocol/fleet_store.h"
#include "protocol/map_store.h"
#include "app/exit_codes.h"
#include "app/password_file.h"
#include "common/core/error.h"
#include "server/cli/command.h"
#include "server/cli/gis_export.h"
#include "server/cli/goal_near_command.h"
#include "server/cli/map_source.h"
#include "server/core/goal_by_node.h"
#include "server/core/goal_check.h"

namespace fleetmap {
namespace {

std::string generate_password() {
  static const char kAlphabet[] = "abcdefghijkmnopqrstuvwxyzABCDEFGHJKLMNPQRSTUVWXYZ23456789";
  std::random_device rd;
  std::string pw;
  for (int i = 0; i < 24; ++i) pw += kAlphabet[rd() % (sizeof kAlphabet - 1)];
  return pw;
}

std::string opt(const std::optional<double>& v, const char* fmt = "%.2f") {
  if (!v) return "-";
  char b[32];
  std::snprintf(b, sizeof b, fmt, *v);
  return b;
}

void finite(std::initializer_list<double> vs) {
  for (double v : vs)
    if (!std::isfinite(v)) throw BadInput("expected finite coordinates");
}

// The profile options of `robot add` and `robot set`, as given on the command line: a
// number, or 'default' for the server's.
struct ProfileOptions {
  std::string laser_height, radius, body_height;  // a number of metres, or "default"
  bool stairs = false, no_stairs = false, ramps = false, no_ramps = false;
};

// What --help shows for them: a number of metres is expected, not any text.
constexpr const char* kMetresOrDefault = "METRES|default";

void add_profile_options(CLI::App& cmd, ProfileOptions& o) {
  cmd.add_option("--laser-height", o.laser_height,
                 "laser mounting height over the floor, m, [0, 1000]: its maps are sliced there (default: the stored map "
                 "unsliced); 'default' clears it")
      ->type_name(kMetresOrDefault);
  cmd.add_option("--radius", o.radius, "radius, m, (0, 100]: kept from obstacles when planning; 'default': the server's")
      ->type_name(kMetresOrDefault);
  cmd.add_option("--height", o.body_height,
                 "body height, m, (0, 1000]: elements starting below it block the robot; 'default': the server's")
      ->type_name(kMetresOrDefault);
  auto* stairs = cmd.add_flag("--stairs", o.stairs, "it can take stairs");
  auto* no_stairs = cmd.add_flag("--no-stairs", o.no_stairs, "it cannot take stairs (the default)");
  auto* ramps = cmd.add_flag("--ramps", o.ramps, "it can take ramps (the default)");
  auto* no_ramps = cmd.add_flag("--no-ramps", o.no_ramps, "it cannot take ramps");
  stairs->excludes(no_stairs);
  ramps->excludes(no_ramps);
}

// "default" -> nullopt (the server's default); a number otherwise. Ranges: check_profile.
std::optional<std::optional<double>> profile_value(const std::string& flag, const std::string& text) {
  if (text.empty()) return std::nullopt;
  if (text == "default") return std::optional<double>();
  size_t used = 0;
  double v = 0;
  try {
    v = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size())
    throw BadInput(flag + ": expected a number of metres or 'default', got '" + text + "'");
  return std::optional<double>(v);
}

RobotProfileChange profile_change(const ProfileOptions& o) {
  RobotProfileChange c;
  c.laser_height = profile_value("--laser-height", o.laser_height);
  c.radius = profile_value("--radius", o.radius);
  c.body_height = profile_value("--height", o.body_height);
  if (o.stairs || o.no_stairs) c.can_stairs = o.stairs;
  if (o.ramps || o.no_ramps) c.can_ramps = o.ramps;
  check_profile(c);
  return c;
}

std::string metres(const std::optional<double>& v) { return v ? opt(v, "%g") : "default"; }

// --json: numbers as numbers, what is unknown as null (the table's '-').
nlohmann::json number_or_null(const std::optional<double>& v) { return v ? nlohmann::json(*v) : nlohmann::json(); }

void print_json(const nlohmann::json& j) { std::cout << j.dump() << std::endl; }

// robot add NAME --map MAP: the robot's own account, its id and its whole profile.
struct RobotAddArgs {
  std::string name, map, password_file, password_out;
  int max_connections = 4;
  ProfileOptions profile;
};

int run_robot_add(const RobotAddArgs& a, CliContext& ctx) {
  // Bad values before the account exists. The whole profile is written: a robot added
  // again keeps its row (sql/40_robot_accounts.sql), not its old profile.
  RobotProfileChange change = profile_change(a.profile);
  if (!change.laser_height) change.laser_height.emplace();
  if (!change.radius) change.radius.emplace();
  if (!change.body_height) change.body_height.emplace();
  if (!change.can_stairs) change.can_stairs = false;
  if (!change.can_ramps) change.can_ramps = true;
  const std::string pw = a.password_file.empty() ? generate_password() : read_password_file(a.password_file);
  // Opened before the account exists: a path that cannot take the password fails first.
  std::optional<PasswordFileOut> out;
  if (a.password_file.empty() && !a.password_out.empty()) out.emplace(a.password_out);
  FleetStore fleet(ctx.connection());
  const unsigned id = fleet.add_robot(a.name, pw, a.map, a.max_connections);
  fleet.set_profile(a.name, change);
  std::printf("robot '%s' added: robot id %u, map '%s'\n", a.name.c_str(), id, a.map.c_str());
  if (a.password_file.empty()) {
    if (out) {
      out->write(pw);
      std::printf("password written to %s\n", a.password_out.c_str());
    } else {
      std::printf("password: %s   (shown once; keep it on the robot)\n", pw.c_str());
    }
  }
  return exit_code::kOk;
}

void add_robot_add(CLI::App& robot, CliContext& ctx) {
  auto a = std::make_shared<RobotAddArgs>();
  auto* cmd = robot.add_subcommand("add", "create a robot's own database account and stable robot id");
  cmd->add_option("NAME", a->name, "account name, [a-z0-9_-]{1,32}")->required();
  cmd->add_option("--map", a->map, "the map this robot works on")->required();
  cmd->add_option("--password-file", a->password_file, "first line: the password (default: generate one)")
      ->check(CLI::ExistingFile);
  cmd->add_option("--password-out", a->password_out,
                  "write the generated password to this file, mode 600 (replaced if it exists; not a symlink)");
  cmd->add_option("--max-connections", a->max_connections, "MAX_USER_CONNECTIONS of the account")
      ->capture_default_str();
  add_profile_options(*cmd, a->profile);
  run_with(*cmd, a, ctx, run_robot_add);
}

// robot list [--json]
struct RobotListArgs {
  bool json = false;
};

int run_robot_list(const RobotListArgs& a, CliContext& ctx) {
  FleetStore fleet(ctx.connection());
  const std::map<std::string, RobotProfile> profiles = fleet.profiles();
  if (a.json) {
    nlohmann::json out = nlohmann::json::array();
    for (const RobotStatus& s : fleet.status()) {
      auto it = profiles.find(s.name);
      const RobotProfile p = it == profiles.end() ? RobotProfile{} : it->second;
      out.push_back({{"id", s.id}, {"name", s.name}, {"map", s.map}, {"state", std::string(to_string(s.state))},
                     {"laser_height", number_or_null(p.laser_height)}, {"radius", number_or_null(p.radius)},
                     {"height", number_or_null(p.body_height)}, {"stairs", p.can_stairs}, {"ramps", p.can_ramps}});
    }
    print_json(out);  // null: the server's default
    return exit_code::kOk;
  }
  std::printf("%-6s %-20s %-20s %-9s %-8s %-8s %-8s %-6s %-5s\n", "ID", "NAME", "MAP", "STATE", "LASER", "RADIUS",
              "HEIGHT", "STAIRS", "RAMPS");
  for (const RobotStatus& s : fleet.status()) {
    auto it = profiles.find(s.name);
    const RobotProfile p = it == profiles.end() ? RobotProfile{} : it->second;
    std::printf("%-6u %-20s %-20s %-9s %-8s %-8s %-8s %-6s %-5s\n", s.id, s.name.c_str(), s.map.c_str(),
                std::string(to_string(s.state)).c_str(), metres(p.laser_height).c_str(), metres(p.radius).c_str(),
                metres(p.body_height).c_str(), p.can_stairs ? "yes" : "no", p.can_ramps ? "yes" : "no");
  }
  return exit_code::kOk;
}

void add_robot_list(CLI::App& robot, CliContext& ctx) {
  auto a = std::make_shared<RobotListArgs>();
  auto* cmd = robot.add_subcommand("list", "list registered robots and their profiles ('default': the server's)");
  cmd->add_flag("--json", a->json, "a JSON array, one object per robot (null: the server's default)");
  run_with(*cmd, a, ctx, run_robot_list);
}

// robot set NAME --radius R ...: a profile change; its next map (Ready, GetMap) follows it.
struct RobotSetArgs {
  std::string name;
  ProfileOptions profile;
};

int run_robot_set(const RobotSetArgs& a, CliContext& ctx) {
  const RobotProfileChange change = profile_change(a.profile);
  if (change.empty())
    throw CLI::ValidationError("robot set", "expected at least one of --laser-height, --radius, --height, "
                                            "--stairs, --no-stairs, --ramps, --no-ramps");
  FleetStore fleet(ctx.connection());
  fleet.set_profile(a.name, change);
  const RobotProfile p = fleet.profile(a.name);
  std::printf("robot '%s': laser height %s, radius %s, height %s, stairs %s, ramps %s\n", a.name.c_str(),
              metres(p.laser_height).c_str(), metres(p.radius).c_str(), metres(p.body_height).c_str(),
              p.can_stairs ? "yes" : "no", p.can_ramps ? "yes" : "no");
  return exit_code::kOk;
}

void add_robot_set(CLI::App& robot, CliContext& ctx) {
  auto a = std::make_shared<RobotSetArgs>();
  auto* cmd = robot.add_subcommand("set", "change a robot's profile; its next map (Ready, GetMap) follows it");
  cmd->add_option("NAME", a->name, "robot name")->required();
  add_profile_options(*cmd, a->profile);
  run_with(*cmd, a, ctx, run_robot_set);
}

// robot remove NAME
struct RobotRemoveArgs {
  std::string name;
};

int run_robot_remove(const RobotRemoveArgs& a, CliContext& ctx) {
  FleetStore(ctx.connection()).remove_robot(a.name);
  std::printf("robot '%s' removed\n", a.name.c_str());
  return exit_code::kOk;
}

void add_robot_remove(CLI::App& robot, CliContext& ctx) {
  auto a = std::make_shared<RobotRemoveArgs>();
  auto* cmd = robot.add_subcommand("remove", "drop a robot's account and end its connections; its history stays");
  cmd->add_option("NAME", a->name, "robot name")->required();
  run_with(*cmd, a, ctx, run_robot_remove);
}

// robots [--json] [--watch S [--count N]]: the status table.
struct RobotsArgs {
  bool json = false;
  double watch_s = 0;  // 0: once
  int count = 0;       // with --watch: stop after this many refreshes (0: until Ctrl-C)
};

nlohmann::json robots_json(const std::vector<RobotStatus>& all) {
  nlohmann::json out = nlohmann::json::array();
  for (const RobotStatus& s : all) {
    nlohmann::json task;  // null without one
    if (s.task_id)
      task = {{"id", *s.task_id},
              {"state", s.task_state ? nlohmann::json(std::string(to_string(*s.task_state))) : nlohmann::json()},
              {"goal", s.goal_x && s.goal_y ? nlohmann::json{*s.goal_x, *s.goal_y} : nlohmann::json()}};
    out.push_back({{"robot", s.name}, {"state", std::string(to_string(s.state))}, {"x", number_or_null(s.x)},
                   {"y", number_or_null(s.y)}, {"theta", number_or_null(s.theta)}, {"v", number_or_null(s.v)},
                   {"last_seen", s.last_seen.empty() ? nlohmann::json() : nlohmann::json(s.last_seen)},
                   {"task", task}});
  }
  return out;
}

void print_robots_table(const std::vector<RobotStatus>& all) {
  std::printf("%-16s %-8s %9s %9s %7s %6s  %-26s %-6s %-12s %s\n", "ROBOT", "STATE", "X", "Y", "THETA", "V",
              "LAST SEEN", "TASK", "TASK STATE", "GOAL");
  for (const RobotStatus& s : all) {
    const std::string goal = s.goal_x ? "(" + opt(s.goal_x) + ", " + opt(s.goal_y) + ")" : "-";
    std::printf("%-16s %-8s %9s %9s %7s %6s  %-26s %-6s %-12s %s\n", s.name.c_str(), std::string(to_string(s.state)).c_str(), opt(s.x).c_str(),
                opt(s.y).c_str(), opt(s.theta).c_str(), opt(s.v).c_str(), s.last_seen.empty() ? "-" : s.last_seen.c_str(),
                s.task_id ? std::to_string(*s.task_id).c_str() : "-", s.task_state ? std::string(to_string(*s.task_state)).c_str() : "-",
                goal.c_str());
  }
}

std::atomic<bool> g_watch_stop{false};
extern "C" void stop_watching(int) { g_watch_stop = true; }

int run_robots(const RobotsArgs& a, CliContext& ctx) {
  FleetStore fleet(ctx.connection());
  if (a.watch_s <= 0) {
    if (a.json) print_json(robots_json(fleet.status()));
    else print_robots_table(fleet.status());
    return exit_code::kOk;
  }
  // Until Ctrl-C (exit 0) or --count refreshes. On a terminal the screen is redrawn; to
  // a pipe or file each refresh is appended (a timestamp line, then the table; with
  // --json one array per line), so a log of it reads back in order.
  std::signal(SIGINT, stop_watching);
  std::signal(SIGTERM, stop_watching);
  const bool tty = isatty(fileno(stdout)) != 0;
  for (int n = 1; !g_watch_stop; ++n) {
    const std::vector<RobotStatus> all = fleet.status();
    if (a.json) {
      print_json(robots_json(all));
    } else {
      const std::time_t now = std::time(nullptr);
      char at[32];
      std::strftime(at, sizeof at, "%Y-%m-%d %H:%M:%S", std::localtime(&now));
      if (tty) std::printf("\033[H\033[2J");
      std::printf("%s  every %g s%s\n", at, a.watch_s, tty ? "; Ctrl-C to stop" : "");
      print_robots_table(all);
      if (!tty) std::printf("\n");
      std::fflush(stdout);
    }
    if (a.count > 0 && n >= a.count) break;
    const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(a.watch_s);
    while (!g_watch_stop && std::chrono::steady_clock::now() < until)
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  return exit_code::kOk;
}

void add_robots(CLI::App& app, CliContext& ctx) {
  auto a = std::make_shared<RobotsArgs>();
  auto* cmd = app.add_subcommand("robots", "status table: state, last pose, last seen, task");
  cmd->add_flag("--json", a->json, "a JSON array, one object per robot (null: unknown)");
  auto* watch = cmd->add_option("--watch", a->watch_s, "refresh every S seconds until Ctrl-C (to a pipe: appended)")
                    ->type_name("S")
                    ->check(CLI::Range(0.1, 3600.0));
  cmd->add_option("--count", a->count, "with --watch: stop after N refreshes")->needs(watch)->check(CLI::PositiveNumber);
  run_with(*cmd, a, ctx, run_robots);
}

// goal ROBOT X Y | goal ROBOT --near TAG | goal ROBOT --node WHAT: a task; the server
// pushes SetPosEnd.
struct GoalArgs {
  std::string robot;
  std::vector<double> xy;
  GoalNearArgs near;
  std::string node;  // --node: a graph node's name, else a node type (server/core/goal_by_node.h)
};

// --node WHAT: the node named WHAT, else the nearest node of that type; refused (exit 3)
// when there is none or the robot cannot reach it.
int assign_goal_at_node(CliContext& ctx, const GoalArgs& a) {
  const AcceptedGoalByNode g =
      accept_goal_by_node(ctx.connection(), ctx.connection(), a.robot, a.node, planning_defaults(ctx.config_path()));
  const TopoNode& n = g.node;
  std::printf("task %llu assigned to '%s': goal node %d%s (%g, %g)", g.goal.task, a.robot.c_str(), n.id,
              n.name.empty() ? "" : (" '" + n.name + "'").c_str(), n.pos.x, n.pos.y);
  if (g.goal.check.from)
    std::printf("; path %.2f m from (%.3f, %.3f)\n", g.goal.check.path_length, g.goal.check.from->x,
                g.goal.check.from->y);
  else
    std::printf("; the robot has no known position yet: only the goal's place was checked\n");
  return exit_code::kOk;
}

int run_goal(const GoalArgs& a, CliContext& ctx) {
  if (int(!a.xy.empty()) + int(!a.near.tag.empty()) + int(!a.node.empty()) != 1)
    throw CLI::ValidationError("expected X Y, --near TAG or --node WHAT (one of them)");
  if (!a.near.tag.empty()) return assign_goal_near(ctx, a.robot, a.near);
  if (!a.node.empty()) return assign_goal_at_node(ctx, a);
  finite({a.xy[0], a.xy[1]});
  // Refused at once when the robot cannot reach it (GoalRefused: exit 3, no task).
  const AcceptedGoal g =
      accept_goal(ctx.connection(), a.robot, {a.xy[0], a.xy[1]}, planning_defaults(ctx.config_path()));
  std::printf("task %llu assigned to '%s': goal (%g, %g)", g.task, a.robot.c_str(), a.xy[0], a.xy[1]);
  if (g.check.from)
    std::printf("; path %.2f m from (%.3f, %.3f)\n", g.check.path_length, g.check.from->x, g.check.from->y);
  else
    std::printf("; the robot has no known position yet: only the goal's place was checked, GetPath plans the "
                "rest\n");
  return exit_code::kOk;
}

void add_goal(CLI::App& app, CliContext& ctx) {
  auto a = std::make_shared<GoalArgs>();
  auto* cmd = app.add_subcommand("goal", "assign a task: the server pushes SetPosEnd to the robot");
  cmd->add_option("ROBOT", a->robot, "robot name")->required();
  cmd->add_option("XY", a->xy, "X Y: the goal (m); or --near TAG, or --node WHAT")->expected(2);
  add_goal_near_options(*cmd, a->near);
  cmd->add_option("--node", a->node,
                  "a node of the map's topological graph: by name (\"room 2.302\"), else the nearest node of that "
                  "type (corridor, room, door, stairs, elevator) to the robot")
      ->type_name("WHAT");
  cmd->footer("A goal X Y is refused at once, and no task is created, when it is outside the map, inside an "
              "obstacle, an object the robot's body cannot pass or an avoided area, or unreachable from the robot's "
              "last pose (or initial pose) with the server's planner for its profile; a lost robot's goals are "
              "refused too (give them again once it reports). Without a known position only the goal's place is "
              "checked. With --near TAG the goal is a free point beside the nearest object with that tag, reachable "
              "the same way (docs/semantic-layer.md). With --node the goal is a node of the robot's map's "
              "topological graph, reachable the same way. Exit codes: 0 assigned, 2 bad value, 3 refused (no path, "
              "goal blocked or outside the map, robot lost; with --near: no free reachable point beside the object; "
              "with --node: no node of that name or type), 4 no such robot, no object with the tag, (--near) no "
              "known position, (--node) no map or no graph, 64 usage.");
  run_with(*cmd, a, ctx, run_goal);
}

// pose-ini ROBOT X Y [THETA]: what the robot gets with GetPosIni.
struct PoseIniArgs {
  std::string robot;
  std::vector<double> pose;
};

int run_pose_ini(const PoseIniArgs& a, CliContext& ctx) {
  for (double v : a.pose)
    if (!std::isfinite(v)) throw BadInput("expected finite numbers for X Y [THETA]");
  std::optional<double> theta;
  if (a.pose.size() == 3) theta = a.pose[2];
  FleetStore(ctx.connection()).set_initial_pose(a.robot, a.pose[0], a.pose[1], theta);
  std::printf("initial pose of '%s' set\n", a.robot.c_str());
  return exit_code::kOk;
}

void add_pose_ini(CLI::App& app, CliContext& ctx) {
  auto a = std::make_shared<PoseIniArgs>();
  auto* cmd = app.add_subcommand("pose-ini", "set the initial pose a robot gets with GetPosIni");
  cmd->add_option("ROBOT", a->robot, "robot name")->required();
  cmd->add_option("POSE", a->pose, "X Y [THETA] (m, m, rad)")->required()->expected(2, 3);
  run_with(*cmd, a, ctx, run_pose_ini);
}

// abort ROBOT: the server pushes Abort; the task is aborted when the robot acknowledges.
struct AbortArgs {
  std::string robot, reason = "aborted by operator";
};

int run_abort(const AbortArgs& a, CliContext& ctx) {
  if (!FleetStore(ctx.connection()).request_abort(a.robot, a.reason)) {
    std::fprintf(stderr, "fleetmap: robot '%s' has no open task\n", a.robot.c_str());
    return exit_code::kNotFound;
  }
  std::printf("abort of the task of '%s' requested\n", a.robot.c_str());
  return exit_code::kOk;
}

void add_abort(CLI::App& app, CliContext& ctx) {
  auto a = std::make_shared<AbortArgs>();
  auto* cmd = app.add_subcommand("abort", "abort the robot's task: the server pushes Abort; aborted when acknowledged");
  cmd->add_option("ROBOT", a->robot, "robot name")->required();
  cmd->add_option("--reason", a->reason, "told to the robot")->capture_default_str();
  run_with(*cmd, a, ctx, run_abort);
}

// tasks [--robot R] [--limit N]: newest first.
struct TasksArgs {
  std::string robot;
  size_t limit = 50;
  bool json = false;
};

int run_tasks(const TasksArgs& a, CliContext& ctx) {
  std::optional<std::string> r;
  if (!a.robot.empty()) r = a.robot;
  if (a.json) {
    nlohmann::json out = nlohmann::json::array();
    for (const TaskInfo& t : FleetStore(ctx.connection()).tasks(r, a.limit))
      out.push_back({{"id", t.id}, {"robot", t.robot}, {"state", std::string(to_string(t.state))}, {"goal", {t.goal_x, t.goal_y}},
                     {"created_at", t.created_at}, {"updated_at", t.updated_at}, {"reason", t.reason}});
    print_json(out);
    return exit_code::kOk;
  }
  std::printf("%-6s %-16s %-13s %10s %10s  %-26s %s\n", "TASK", "ROBOT", "STATE", "GOAL X", "GOAL Y", "UPDATED",
              "REASON");
  for (const TaskInfo& t : FleetStore(ctx.connection()).tasks(r, a.limit))
    std::printf("%-6llu %-16s %-13s %10.2f %10.2f  %-26s %s\n", t.id, t.robot.c_str(), std::string(to_string(t.state)).c_str(), t.goal_x,
                t.goal_y, t.updated_at.c_str(), t.reason.c_str());
  return exit_code::kOk;
}

void add_tasks(CLI::App& app, CliContext& ctx) {
  auto a = std::make_shared<TasksArgs>();
  auto* cmd = app.add_subcommand("tasks", "tasks, newest first");
  cmd->add_option("--robot", a->robot, "only this robot's");
  cmd->add_option("--limit", a->limit, "at most this many")->capture_default_str();
  cmd->add_flag("--json", a->json, "a JSON array, newest first");
  run_with(*cmd, a, ctx, run_tasks);
}

// trajectory ROBOT [--since T] [--format csv|geojson|gpkg|fgb|DRIVER] [--crs ..] [-o FILE]:
// the robot's reported poses, times in ISO 8601 UTC.
struct TrajectoryArgs {
  std::string robot, since, format = "csv", out;
  GisExportArgs gis;
};

int run_trajectory(const TrajectoryArgs& a, CliContext& ctx) {
  std::optional<std::string> s;
  if (!a.since.empty()) s = a.since;
  FleetStore fleet(ctx.connection());
  const Track track = load_track(fleet, a.robot, s);
  if (a.format == "csv") {
    std::string text = "t,x,y,theta,v\n";
    char line[160];
    for (const TrackPose& p : track.poses) {
      std::snprintf(line, sizeof line, ",%.17g,%.17g,%.17g,%.17g\n", p.pos.x, p.pos.y, p.theta, p.v);
      text += p.t + line;
    }
    write_output(text, a.out);
    return exit_code::kOk;
  }
  // The frame is the robot's map's: its georeference gives WGS 84.
  std::string map;
  for (const RobotStatus& r : fleet.status())
    if (r.name == a.robot) map = r.map;
  const MapInfo info = MapStore(ctx.connection()).info(map);
  if (a.format == "geojson") {
    write_output(write_trajectory_geojson({track}, map, geojson_frame(a.gis, map, info.georef)), a.out);
  } else {
    OgrExport e(a.out, ogr_export_options(a.gis, a.format, a.out, map, info.georef));
    e.add_tracks({track});
    finish_ogr_export(e, a.out);
  }
  return exit_code::kOk;
}

void add_trajectory(CLI::App& app, CliContext& ctx) {
  auto a = std::make_shared<TrajectoryArgs>();
  auto* cmd = app.add_subcommand("trajectory", "a robot's reported poses (times in ISO 8601, UTC)");
  cmd->add_option("ROBOT", a->robot, "robot name")->required();
  cmd->add_option("--since", a->since, "a timestamp ('2026-11-28 07:00:00', the database session's time zone) or an "
                                       "age (90s, 10m, 2h, 1d)")
      ->type_name("TIME|AGE")
      ->check([](const std::string& s) {
        static const std::regex kForm(R"(^(\d+[smhd]|\d{4}-\d{2}-\d{2}( \d{2}:\d{2}(:\d{2}(\.\d{1,6})?)?)?)$)");
        return std::regex_match(s, kForm) ? std::string() : "expected a timestamp or an age like 10m, got '" + s + "'";
      });
  cmd->add_option("--format", a->format,
                  "csv, geojson (points with t, theta, v), gpkg, fgb or a GDAL vector driver's short name")
      ->capture_default_str();
  cmd->add_option("-o,--output", a->out, "output file (default: standard output; GDAL formats need one)");
  add_gis_export_options(cmd, a->gis);
  run_with(*cmd, a, ctx, run_trajectory);
}

}  // namespace

void add_robot_commands(CLI::App& app, CliContext& ctx) {
  auto* robot = app.add_subcommand("robot", "register and remove robot accounts");
  robot->require_subcommand(1);
  add_robot_add(*robot, ctx);
  add_robot_list(*robot, ctx);
  add_robot_set(*robot, ctx);
  add_robot_remove(*robot, ctx);
  add_robots(app, ctx);
  add_goal(app, ctx);
  add_pose_ini(app, ctx);
  add_abort(app, ctx);
  add_tasks(app, ctx);
  add_trajectory(app, ctx);
}

}  // namespace fleetmap
