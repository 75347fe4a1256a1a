#include "server/cli/robot_commands.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <random>
#include <regex>
#include <sstream>

#include <nlohmann/json.hpp>

#include "protocol/fleet_store.h"
#include "app/exit_codes.h"
#include "server/cli/goal_near_command.h"

namespace fleetmap {
namespace {

std::string read_password(const std::string& file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error("cannot read password file '" + file + "'");
  std::string pw;
  std::getline(in, pw);
  return pw;
}

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
    if (!std::isfinite(v)) throw std::invalid_argument("expected finite coordinates");
}

// The profile options of `robot add` and `robot set` (issue 8), as given on the command line.
struct ProfileOptions {
  std::string laser_height, radius, body_height;  // a number of metres, or "default"
  bool stairs = false, no_stairs = false, ramps = false, no_ramps = false;
};

void add_profile_options(CLI::App& cmd, ProfileOptions& o) {
  cmd.add_option("--laser-height", o.laser_height,
                 "laser mounting height over the floor, m, [0, 1000]: its maps are sliced there (default: the stored map "
                 "unsliced); 'default' clears it");
  cmd.add_option("--radius", o.radius, "radius, m, (0, 100]: kept from obstacles when planning; 'default': the server's");
  cmd.add_option("--height", o.body_height,
                 "body height, m, (0, 1000]: elements starting below it block the robot; 'default': the server's");
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
    throw std::invalid_argument(flag + ": expected a number of metres or 'default', got '" + text + "'");
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

}  // namespace

void add_robot_commands(CLI::App& app, CliContext& ctx, int* exit_code) {
  auto* robot = app.add_subcommand("robot", "register and remove robot accounts");
  robot->require_subcommand(1);
  {
    auto name = std::make_shared<std::string>();
    auto map = std::make_shared<std::string>();
    auto pw_file = std::make_shared<std::string>();
    auto pw_out = std::make_shared<std::string>();
    auto max_conn = std::make_shared<int>(4);
    auto* cmd = robot->add_subcommand("add", "create a robot's own database account and stable robot id");
    cmd->add_option("NAME", *name, "account name, [a-z0-9_-]{1,32}")->required();
    cmd->add_option("--map", *map, "the map this robot works on")->required();
    cmd->add_option("--password-file", *pw_file, "first line: the password (default: generate one)")
        ->check(CLI::ExistingFile);
    cmd->add_option("--password-out", *pw_out, "write the generated password to this file (mode 600)");
    cmd->add_option("--max-connections", *max_conn, "MAX_USER_CONNECTIONS of the account")->capture_default_str();
    auto profile = std::make_shared<ProfileOptions>();
    add_profile_options(*cmd, *profile);
    cmd->callback([=, &ctx] {
      // Bad values before the account exists. The whole profile is written: a robot added
      // again keeps its row (sql/40_robot_accounts.sql), not its old profile.
      RobotProfileChange change = profile_change(*profile);
      if (!change.laser_height) change.laser_height.emplace();
      if (!change.radius) change.radius.emplace();
      if (!change.body_height) change.body_height.emplace();
      if (!change.can_stairs) change.can_stairs = false;
      if (!change.can_ramps) change.can_ramps = true;
      const std::string pw = pw_file->empty() ? generate_password() : read_password(*pw_file);
      FleetStore fleet(ctx.connection());
      const unsigned id = fleet.add_robot(*name, pw, *map, *max_conn);
      fleet.set_profile(*name, change);
      std::printf("robot '%s' added: robot id %u, map '%s'\n", name->c_str(), id, map->c_str());
      if (pw_file->empty()) {
        if (!pw_out->empty()) {
          std::ofstream out(*pw_out);
          out << pw << "\n";
          std::printf("password written to %s\n", pw_out->c_str());
        } else {
          std::printf("password: %s   (shown once; keep it on the robot)\n", pw.c_str());
        }
      }
      *exit_code = exit_code::kOk;
    });
  }
  {
    auto* cmd = robot->add_subcommand("list", "list registered robots and their profiles ('default': the server's)");
    cmd->callback([=, &ctx] {
      FleetStore fleet(ctx.connection());
      const std::map<std::string, RobotProfile> profiles = fleet.profiles();
      std::printf("%-6s %-20s %-20s %-9s %-8s %-8s %-8s %-6s %-5s\n", "ID", "NAME", "MAP", "STATE", "LASER", "RADIUS",
                  "HEIGHT", "STAIRS", "RAMPS");
      for (const RobotStatus& s : fleet.status()) {
        auto it = profiles.find(s.name);
        const RobotProfile p = it == profiles.end() ? RobotProfile{} : it->second;
        std::printf("%-6u %-20s %-20s %-9s %-8s %-8s %-8s %-6s %-5s\n", s.id, s.name.c_str(), s.map.c_str(),
                    std::string(to_string(s.state)).c_str(), metres(p.laser_height).c_str(), metres(p.radius).c_str(),
                    metres(p.body_height).c_str(), p.can_stairs ? "yes" : "no", p.can_ramps ? "yes" : "no");
      }
      *exit_code = exit_code::kOk;
    });
  }
  {
    auto name = std::make_shared<std::string>();
    auto profile = std::make_shared<ProfileOptions>();
    auto* cmd = robot->add_subcommand("set", "change a robot's profile; its next map (Ready, GetMap) follows it");
    cmd->add_option("NAME", *name, "robot name")->required();
    add_profile_options(*cmd, *profile);
    cmd->callback([=, &ctx] {
      const RobotProfileChange change = profile_change(*profile);
      if (change.empty())
        throw CLI::ValidationError("robot set", "expected at least one of --laser-height, --radius, --height, "
                                                "--stairs, --no-stairs, --ramps, --no-ramps");
      FleetStore fleet(ctx.connection());
      fleet.set_profile(*name, change);
      const RobotProfile p = fleet.profile(*name);
      std::printf("robot '%s': laser height %s, radius %s, height %s, stairs %s, ramps %s\n", name->c_str(),
                  metres(p.laser_height).c_str(), metres(p.radius).c_str(), metres(p.body_height).c_str(),
                  p.can_stairs ? "yes" : "no", p.can_ramps ? "yes" : "no");
      *exit_code = exit_code::kOk;
    });
  }
  {
    auto name = std::make_shared<std::string>();
    auto* cmd = robot->add_subcommand("remove", "drop a robot's account and end its connections; its history stays");
    cmd->add_option("NAME", *name, "robot name")->required();
    cmd->callback([=, &ctx] {
      FleetStore(ctx.connection()).remove_robot(*name);
      std::printf("robot '%s' removed\n", name->c_str());
      *exit_code = exit_code::kOk;
    });
  }
  {
    auto* cmd = app.add_subcommand("robots", "status table: state, last pose, last seen, task");
    cmd->callback([=, &ctx] {
      FleetStore fleet(ctx.connection());
      std::printf("%-16s %-8s %9s %9s %7s %6s  %-26s %-6s %-12s %s\n", "ROBOT", "STATE", "X", "Y", "THETA", "V",
                  "LAST SEEN", "TASK", "TASK STATE", "GOAL");
      for (const RobotStatus& s : fleet.status()) {
        const std::string goal = s.goal_x ? "(" + opt(s.goal_x) + ", " + opt(s.goal_y) + ")" : "-";
        std::printf("%-16s %-8s %9s %9s %7s %6s  %-26s %-6s %-12s %s\n", s.name.c_str(),
                    std::string(to_string(s.state)).c_str(),
                    opt(s.x).c_str(), opt(s.y).c_str(), opt(s.theta).c_str(), opt(s.v).c_str(),
                    s.last_seen.empty() ? "-" : s.last_seen.c_str(),
                    s.task_id ? std::to_string(*s.task_id).c_str() : "-", s.task_state ? std::string(to_string(*s.task_state)).c_str() : "-",
                    goal.c_str());
      }
      *exit_code = exit_code::kOk;
    });
  }
  {
    auto name = std::make_shared<std::string>();
    auto xy = std::make_shared<std::vector<double>>();
    auto near = std::make_shared<GoalNearArgs>();
    auto* cmd = app.add_subcommand("goal", "assign a task: the server pushes SetPosEnd to the robot");
    cmd->add_option("ROBOT", *name, "robot name")->required();
    cmd->add_option("XY", *xy, "X Y: the goal (m); or --near TAG")->expected(2);
    add_goal_near_options(*cmd, *near);
    cmd->footer("With --near TAG the goal is a free point beside the nearest object with that tag, reachable from the "
                "robot's last pose (or initial pose) with the server's planner (docs/semantic-layer.md). Exit codes: 0 "
                "assigned, 2 bad value, 3 no free reachable point beside the object, 4 no such robot, no object with "
                "the tag, or no known position, 64 usage.");
    cmd->callback([=, &ctx] {
      if (xy->empty() == near->tag.empty()) throw CLI::ValidationError("expected X Y or --near TAG (one of them)");
      if (!near->tag.empty()) {
        *exit_code = assign_goal_near(ctx, *name, *near);
        return;
      }
      finite({(*xy)[0], (*xy)[1]});
      const auto task = FleetStore(ctx.connection()).assign_goal(*name, (*xy)[0], (*xy)[1]);
      std::printf("task %llu assigned to '%s': goal (%g, %g)\n", task, name->c_str(), (*xy)[0], (*xy)[1]);
      *exit_code = exit_code::kOk;
    });
  }
  {
    auto name = std::make_shared<std::string>();
    auto pose = std::make_shared<std::vector<double>>();
    auto* cmd = app.add_subcommand("pose-ini", "set the initial pose a robot gets with GetPosIni");
    cmd->add_option("ROBOT", *name, "robot name")->required();
    cmd->add_option("POSE", *pose, "X Y [THETA] (m, m, rad)")->required()->expected(2, 3);
    cmd->callback([=, &ctx] {
      for (double v : *pose)
        if (!std::isfinite(v)) throw std::invalid_argument("expected finite numbers for X Y [THETA]");
      std::optional<double> theta;
      if (pose->size() == 3) theta = (*pose)[2];
      FleetStore(ctx.connection()).set_initial_pose(*name, (*pose)[0], (*pose)[1], theta);
      std::printf("initial pose of '%s' set\n", name->c_str());
      *exit_code = exit_code::kOk;
    });
  }
  {
    auto name = std::make_shared<std::string>();
    auto reason = std::make_shared<std::string>("aborted by operator");
    auto* cmd = app.add_subcommand("abort", "abort the robot's task: the server pushes Abort; aborted when acknowledged");
    cmd->add_option("ROBOT", *name, "robot name")->required();
    cmd->add_option("--reason", *reason, "told to the robot")->capture_default_str();
    cmd->callback([=, &ctx] {
      if (!FleetStore(ctx.connection()).request_abort(*name, *reason)) {
        std::fprintf(stderr, "fleetmap: robot '%s' has no open task\n", name->c_str());
        *exit_code = exit_code::kNotFound;
        return;
      }
      std::printf("abort of the task of '%s' requested\n", name->c_str());
      *exit_code = exit_code::kOk;
    });
  }
  {
    auto name = std::make_shared<std::string>();
    auto limit = std::make_shared<size_t>(50);
    auto* cmd = app.add_subcommand("tasks", "tasks, newest first");
    cmd->add_option("--robot", *name, "only this robot's");
    cmd->add_option("--limit", *limit, "at most this many")->capture_default_str();
    cmd->callback([=, &ctx] {
      std::optional<std::string> r;
      if (!name->empty()) r = *name;
      std::printf("%-6s %-16s %-13s %10s %10s  %-26s %s\n", "TASK", "ROBOT", "STATE", "GOAL X", "GOAL Y", "UPDATED",
                  "REASON");
      for (const TaskInfo& t : FleetStore(ctx.connection()).tasks(r, *limit))
        std::printf("%-6llu %-16s %-13s %10.2f %10.2f  %-26s %s\n", t.id, t.robot.c_str(), std::string(to_string(t.state)).c_str(), t.goal_x,
                    t.goal_y, t.updated_at.c_str(), t.reason.c_str());
      *exit_code = exit_code::kOk;
    });
  }
  {
    auto name = std::make_shared<std::string>();
    auto since = std::make_shared<std::string>();
    auto format = std::make_shared<std::string>("csv");
    auto* cmd = app.add_subcommand("trajectory", "a robot's reported poses");
    cmd->add_option("ROBOT", *name, "robot name")->required();
    cmd->add_option("--since", *since, "a timestamp ('2026-11-28 07:00:00') or an age (90s, 10m, 2h, 1d)")
        ->check([](const std::string& s) {
          static const std::regex kForm(R"(^(\d+[smhd]|\d{4}-\d{2}-\d{2}( \d{2}:\d{2}(:\d{2}(\.\d{1,6})?)?)?)$)");
          return std::regex_match(s, kForm) ? std::string() : "expected a timestamp or an age like 10m, got '" + s + "'";
        });
    cmd->add_option("--format", *format, "csv or geojson")->check(CLI::IsMember({"csv", "geojson"}))->capture_default_str();
    cmd->callback([=, &ctx] {
      std::optional<std::string> s;
      if (!since->empty()) s = *since;
      const auto pts = FleetStore(ctx.connection()).trajectory(*name, s);
      if (*format == "csv") {
        std::printf("t,x,y,theta,v\n");
        for (const auto& p : pts) std::printf("%s,%.17g,%.17g,%.17g,%.17g\n", p.t.c_str(), p.x, p.y, p.theta, p.v);
      } else {
        nlohmann::json coords = nlohmann::json::array(), times = nlohmann::json::array();
        for (const auto& p : pts) {
          coords.push_back({p.x, p.y});
          times.push_back(p.t);
        }
        nlohmann::json f = {{"type", "Feature"},
                            {"geometry", {{"type", "LineString"}, {"coordinates", coords}}},
                            {"properties", {{"robot", *name}, {"times", times}, {"frame", "map"}}}};
        std::cout << nlohmann::json{{"type", "FeatureCollection"}, {"features", {f}}}.dump() << "\n";
      }
      *exit_code = exit_code::kOk;
    });
  }
}

}  // namespace fleetmap
