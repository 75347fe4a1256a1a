// fleetmap-server: the map server daemon (SPEC 5). Parses options, then runs worker
// threads of RequestLoop until SIGTERM or SIGINT; each finishes the transaction in hand.
#include <csignal>
#include <cstdlib>
#include <iostream>
#include <thread>
#include <vector>

#include <CLI/CLI.hpp>
#include <spdlog/spdlog.h>

#include "protocol/connection.h"
#include "app/cli_context.h"
#include "app/exit_codes.h"
#include "app/run_program.h"
#include "server/daemon/request_loop.h"
#include "server/daemon/stall_guard.h"

namespace {
std::atomic<bool> g_stop{false};
extern "C" void on_signal(int) { g_stop = true; }
}  // namespace

int main(int argc, char** argv) {
  using namespace fleetmap;
  CLI::App app{"fleetmap-server: the fleetmap map server. Robots insert requests into rr; the server answers in sa "
               "(SPEC 5). Settings: the [server] section of the config file, overridden by the flags below."};
  CliContext ctx(Role::Server);
  ctx.add_connection_options(app);
  ServerConfig cfg;
  std::map<std::string, std::string> flags;
  // The value goes to ServerConfig::apply as text, like the config file's (one check, one
  // message); type is what --help shows.
  auto setting = [&](const std::string& flag, const std::string& key, const std::string& type, const std::string& help) {
    app.add_option_function<std::string>(flag, [&flags, key](const std::string& v) { flags[key] = v; }, help)
        ->type_name(type);
  };
  setting("--alive-period", "alive_period_s", "SECONDS", "Alive period told to robots, s (default 1)");
  setting("--lost-after", "lost_after_periods", "FLOAT", "silent this many Alive periods -> lost (default 5)");
  setting("--workers", "workers", "UINT", "worker threads, each with its own connection (default 2)");
  setting("--poll-max-ms", "poll_max_ms", "MS", "idle polling back-off ceiling, ms (default 10)");
  setting("--batch-robots", "batch_robots", "UINT", "robots claimed per transaction (default 16)");
  setting("--batch-requests", "batch_requests", "UINT", "requests of one robot per transaction (default 32)");
  setting("--max-full-map-segments", "max_full_map_segments", "UINT",
          "larger maps go out as a window on Ready (default 20000)");
  setting("--ready-window", "ready_window_m", "METRES", "side of that window, m (default 100)");
  setting("--max-window", "max_window_m", "METRES", "GetMap sides are capped to this, m (default 1000)");
  setting("--max-image-bytes", "max_image_bytes", "BYTES", "SendImage payload limit (default 8 MiB)");
  setting("--goal-tolerance", "goal_tolerance_m", "METRES",
          "Stopped within this of the goal -> task done, m (default 0.5)");
  setting("--robot-radius", "robot_radius_m", "METRES", "radius robots are planned with (GetPath), m (default 0.3)");
  setting("--object-ttl", "object_ttl_s", "SECONDS",
          "SetObject: an observed object expires this long after it was last seen, s (default 300)");
  setting("--history-keep", "history_keep_s", "SECONDS",
          "delete trajectory rows and GPS fixes older than this, s (default 0: keep them all)");
  setting("--robot-block-ms", "robot_block_ms", "MS",
          "a robot connection that blocks another robot's this long is ended, ms (default 2000)");
  setting("--partition", "partition", "I/N",
          "serve only the robots whose id mod N is I, so that N servers (e.g. on N Galera nodes) share the fleet "
          "without claiming the same robot; also $FLEETMAP_SERVER_PARTITION (default 0/1: every robot)");
  setting("--commit-delay-ms", "commit_delay_ms", "MS",
          "tests only: wait this long before each batch's COMMIT, so that a SIGKILL lands in flight (default 0)");
  std::string log_level = "info";
  app.add_option("--log-level", log_level, "trace, debug, info, warn, error")->capture_default_str();
  bool check = false;
  app.add_flag("--check", check, "connect with the server account, print the settings, and exit");
  app.footer("Exit codes: 0 stopped cleanly, 1 failure, 2 bad setting, 64 usage.");
  return run_program("fleetmap-server", app, argc, argv, [&]() -> int {
    spdlog::set_level(spdlog::level::from_str(log_level));
    spdlog::set_pattern("%Y-%m-%d %H:%M:%S.%e %^%-5l%$ %v");

    // A bad setting is exit 2, an unreadable config file or no database 1 (exit_code_for).
    const DbSettings db = ctx.settings();
    cfg.apply(db.program);
    // Between the file and the flags, as FLEETMAP_* are for the connection: a service
    // unit or container sets a server's share without a file of its own.
    if (const char* p = std::getenv("FLEETMAP_SERVER_PARTITION"); p && *p) {
      try {
        cfg.apply({{"partition", p}});
      } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(std::string("FLEETMAP_SERVER_PARTITION: ") + e.what());  // exit 2
      }
    }
    cfg.apply(flags);
    if (check) {
      connect(db);
      std::cout << "fleetmap-server: connected as " << describe(db) << "; alive period " << cfg.alive_period_s
                << " s, " << cfg.workers << " workers, robots " << (cfg.partition.all() ? "all" : "with id mod " +
                std::to_string(cfg.partition.count) + " = " + std::to_string(cfg.partition.index)) << "\n";
      return exit_code::kOk;
    }

    // No account (no config file found): exit 1 at once; an unreachable database is
    // waited for (request_loop.h), logged once per back-off step.
    check_account(db);
    std::signal(SIGTERM, on_signal);
    std::signal(SIGINT, on_signal);
    spdlog::info("fleetmap-server starting: {} worker(s), database {}, robots {}", cfg.workers, describe(db),
                 cfg.partition.all() ? std::string("all") : "of partition " + cfg.partition.text());
    MapCache cache;
    PlannerCache planners;
    TopoCache graphs;  // the maps' topological graphs, for GetPath
    std::vector<std::thread> workers;
    for (int i = 0; i < cfg.workers; ++i)
      workers.emplace_back([&, i] { RequestLoop(db, cfg, cache, planners, graphs, g_stop, i, i == 0).run(); });
    workers.emplace_back([&] { StallGuard(db, g_stop, std::chrono::milliseconds(250),
                                                  std::chrono::duration<double, std::milli>(cfg.robot_block_ms))
                                           .run(); });
    for (auto& t : workers) t.join();
    spdlog::info("fleetmap-server stopped");
    return exit_code::kOk;
  });
}
