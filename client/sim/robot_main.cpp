// fleetmap-robot: a simulated robot that speaks RR/SA with its own account (SPEC 6).
// Parses options and runs client/sim/SimRobot; with --trials, runs the localization
// trials of bench-localization instead (client/sim/localization_trials.h), no
// database needed.
#include <csignal>
#include <unistd.h>

#include <iostream>

#include <CLI/CLI.hpp>
#include <spdlog/spdlog.h>

#include "app/exit_codes.h"
#include "app/maps_dir.h"
#include "app/password_file.h"
#include "app/run_program.h"
#include "client/robot_client.h"
#include "client/sim/localization_trials.h"
#include "client/sim/sim_robot.h"
#include "client/sim/tour_run.h"
#include "common/io/tour_json.h"
#include "common/core/error.h"
#include "common/io/amrl_import.h"
#include "common/io/read_map_file.h"
#include "common/raycast/grid_ray_caster.h"
#include "common/io/seed_format.h"
#include "protocol/connection.h"

namespace {
std::atomic<bool> g_stop{false};
extern "C" void on_signal(int) { g_stop = true; }

// --trials: the report of bench-localization through the same runner, with the robot's
// laser and particle count. Returns the exit code; errors are thrown (run_program).
int run_trials(int trials, std::vector<std::string> maps, const std::string& presets, bool skip_tracking,
               int look_around, const fleetmap::SimRobotOptions& o) {
  namespace loc = fleetmap::localization;
  loc::TrialSettings s;
  s.trials = trials;
  s.updates = 10;  // localized means: within 10 laser updates (docs/localization.md)
  s.look_around = look_around;
  s.seed = o.seed;
  s.laser = o.laser;
  s.filter.particles = o.global_particles;
  s.filter.beams = o.laser.beams;
  s.filter.fov = o.laser.fov;
  s.filter.laser = {o.laser_height, 15.0};
  std::vector<std::string> names;
  for (size_t at = 0; at <= presets.size();) {
    const size_t comma = std::min(presets.find(',', at), presets.size());
    names.push_back(presets.substr(at, comma - at));
    at = comma + 1;
  }
  for (const std::string& n : names)
    if (!loc::preset(n)) throw fleetmap::UsageError("--presets: expected seed, robust, search or fast, got " + n);
  if (maps.empty()) maps = {fleetmap::real_map_path("GDC1.vectormap.txt"), fleetmap::real_map_path("UT_Campus.vectormap.txt")};
  for (const std::string& path : maps) {
    const fleetmap::Map map = loc::load_map_file(path);  // MapFormatError: exit 2
    std::shared_ptr<const fleetmap::RayCaster> world = std::make_shared<fleetmap::GridRayCaster>(map, s.filter.laser);
    loc::report_map_header(stdout, path, map, s);
    for (const std::string& n : names) loc::report_preset(stdout, map, world, s, n, true, !skip_tracking);
  }
  return fleetmap::exit_code::kOk;
}
}  // namespace

int main(int argc, char** argv) {
  using namespace fleetmap;
  CLI::App app{"fleetmap-robot: a simulated robot (differential drive, noisy odometry, 2D laser, compass) that "
               "registers with the fleetmap server, localizes on the maps it receives, reports its pose at 3 Hz "
               "and drives to the goals operators give it."};
  std::optional<std::string> config, host, hosts, user, password_file, world;
  std::optional<unsigned> port;
  std::vector<double> start, kidnap;
  double duration = 1e9;
  SimRobotOptions o;
  long long magic = 0;
  std::string log_level = "info";
  app.add_option("--config", config, "config file (the [robot] section: user, password or password_file)");
  app.add_option("--host", host, "database host");
  app.add_option("--port", port, "database TCP port");
  app.add_option("--hosts", hosts,
                 "database nodes to fail over between, in order: 'host[:port],host[:port],...' (a Galera cluster; "
                 "a host without :port has --port); overrides [database] hosts and $FLEETMAP_HOSTS")
      ->type_name("LIST");
  app.add_option("--user", user, "the robot's account");
  app.add_option("--password-file", password_file, "file holding the account's password")->check(CLI::ExistingFile);
  app.add_option("--world", world, "ground-truth map file (seed or AMRL); default: the map the server sends on Ready");
  app.add_option("--start", start, "true start pose X Y THETA (m, m, rad); required unless --trials")->expected(3);
  app.add_option("--duration", duration, "stop after this many seconds");
  app.add_option("--kidnap", kidnap,
                 "T X Y THETA: at T seconds move the true robot to (X, Y, THETA) without odometry; the lost detector "
                 "should notice, report it (SendPos status lost) and localize again")
      ->expected(4);
  app.add_option("--laser-height", o.laser_height, "laser mounting height hL (m)")->capture_default_str();
  app.add_option("--beams", o.laser.beams, "laser beams NL")->capture_default_str();
  app.add_option("--laser-sigma", o.laser.sigma, "laser noise sigma_L (m)")->capture_default_str();
  app.add_option("--people", o.laser.people, "unmodelled obstacles (people) per scan")->capture_default_str();
  app.add_option("--localizer", o.localizer,
                 "global localization's filter preset: fast (one coarse-to-fine search at the end of the look "
                 "around, people left out of it; under 1 s), or search (a search per scan; about 10 s); "
                 "docs/localization.md")
      ->check(CLI::IsMember({"fast", "search"}))
      ->capture_default_str();
  app.add_option("--particles", o.global_particles, "particles for global localization (NP)")->capture_default_str();
  app.add_option("--tracking-particles", o.tracking_particles, "max particles while tracking (KLD)")->capture_default_str();
  app.add_option("--speed", o.pursuit.max_speed, "max speed (m/s)")->capture_default_str();
  app.add_flag("--zoom", o.zoom, "keep a map window around the robot (GetMap) instead of the whole map");
  app.add_option("--zoom-window", o.zoom_options.window_m, "zoom window side (m)")->capture_default_str();
  app.add_option("--seed", o.seed, "random seed")->capture_default_str();
  int max_updates = 60;
  bool force_global = false;
  app.add_flag("--global", force_global, "localize globally even when an operator set an initial pose");
  app.add_option("--localize-updates", max_updates, "scans allowed for global localization")->capture_default_str();
  app.add_option("--magic", magic, "magic of the Ready (default: the process id)");
  app.add_option("--log-level", log_level, "trace, debug, info, warn, error")->capture_default_str();
  int trials = 0;
  std::vector<std::string> map_files;
  std::string presets = "seed,search";
  bool skip_tracking = false;
  app.add_option("--trials", trials,
                 "run N global localization trials per map (and a 200 m tracking run) on simulated sensors, print "
                 "the report of bench-localization and exit; no database");
  app.add_option("--map-file", map_files, "maps for --trials (AMRL .vectormap.txt, seed .map, or gen:offices, "
                                          "gen:corridor, gen:hall, gen:clutter); default "
                                          "GDC1 and UT_Campus in " + fleetmap::maps_dir() +
                                          " ($FLEETMAP_MAPS_DIR)");
  app.add_option("--presets", presets, "filter presets for --trials, comma-separated: seed (the baseline), robust, "
                                       "search (the robot's)")->capture_default_str();
  app.add_flag("--skip-tracking", skip_tracking, "--trials: global localization only");
  int look_around = fleetmap::localization::TrialSettings{}.look_around;
  app.add_option("--look-around", look_around,
                 "--trials: scans turning 60 degrees in place before wandering (0: wander from the first)")
      ->capture_default_str();
  std::optional<std::string> tour_file;
  TourRunOptions tour_options;
  app.add_option("--tour", tour_file,
                 "follow a simulated guide along this tour file (JSON list of {x, y, event?, name?}) and send "
                 "TourEvent at its events (docs/topology-tour.md); --start is not needed")
      ->check(CLI::ExistingFile);
  app.add_option("--tour-name", tour_options.tour, "TourEvent params.tour (default: the robot's unnamed tour)");
  app.add_option("--follow", tour_options.walk.follow_distance, "--tour: metres behind the guide")->capture_default_str();
  bool tour_fast = false;
  app.add_flag("--tour-fast", tour_fast, "--tour: run as fast as the server answers, not in real time");
  app.footer("Exit codes: 0 ok, 1 failure (database, server), 2 bad input, 5 localization failed, 64 usage.");
  return run_program("fleetmap-robot", app, argc, argv, [&]() -> int {
    if (trials > 0) return run_trials(trials, map_files, presets, skip_tracking, look_around, o);
    if (start.size() != 3 && !tour_file) throw UsageError("--start X Y THETA is required (or --trials N, or --tour FILE)");
    spdlog::set_level(spdlog::level::from_str(log_level));
    spdlog::set_pattern("%H:%M:%S.%e %^%-5l%$ [robot] %v");
    std::signal(SIGTERM, on_signal);
    std::signal(SIGINT, on_signal);
    DbSettings s = load_settings(Role::Robot, config);
    if (host) { s.host = *host; s.socket.clear(); s.hosts.clear(); }  // one host: no failover list
    if (port) s.port = *port;
    if (hosts) s.hosts = parse_hosts(*hosts, "--hosts");  // BadInput: exit 2
    if (user) s.user = *user;
    if (password_file) s.password = read_password_file(*password_file);
    s.socket.clear();  // robots connect over the network, as real ones do
    // The [robot] section's wait_* settings: how often sa_mine is polled (protocol/wait_policy.h).
    WaitPolicy wait;
    try {
      wait.apply(s.program);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(std::string("[robot] ") + e.what());  // exit 2, a bad setting
    }
    RobotClient client(s, std::chrono::seconds(60), wait);
    const RobotSession session = client.ready(magic ? magic : getpid());
    spdlog::info("registered as robot {} ({}); map of {} segments", session.robot_id, s.user, session.map.segment_count());
    client.start_alive(std::chrono::milliseconds(static_cast<int>(session.alive_period_s * 1000)));
    if (tour_file) {
      const std::vector<TourWaypoint> tour = read_tour_json_file(*tour_file);
      tour_options.realtime = !tour_fast;
      const size_t n = run_guided_tour(client, tour, tour_options, g_stop);
      spdlog::info("tour done: {} events acknowledged; build it with 'fleetmap topo tour build MAP --robot {}'", n,
                   s.user);
      return exit_code::kOk;
    }
    Map truth = session.map;
    if (world) truth = read_map_file(*world);
    if (kidnap.size() == 4) {
      o.kidnap_at_s = kidnap[0];
      o.kidnap_to = {kidnap[1], kidnap[2], kidnap[3]};
    }
    SimRobot robot(client, truth, {start[0], start[1], start[2]}, session.map, o);
    // An operator's initial pose (GetPosIni) starts tracking from it, as with AMCL's
    // initial pose; without one, or with --global, the robot localizes globally.
    const auto ini_id = client.send(RequestOp::GetPosIni);
    const auto ini = client.await(ini_id, 1);
    if (ini[0].op == "SetPosIni" && !force_global) {
      const SetPoseParams p = decode_set_pose(ini[0].params);
      spdlog::info("tracking from the operator's initial pose ({:.2f}, {:.2f})", p.x, p.y);
      robot.start_tracking({p.x, p.y, p.theta.value_or(0)}, 0.3, p.theta ? 0.05 : 3.2);
    } else if (!robot.localize(max_updates)) {
      throw LocalizationFailed("global localization failed; set an initial pose (fleetmap pose-ini) and restart");
    }
    robot.run(g_stop, duration);
    spdlog::info("stopped: {} goal(s) reached, {} refused by the server (no path)", robot.goals_reached(), robot.goals_refused());
    return exit_code::kOk;
  });
}
