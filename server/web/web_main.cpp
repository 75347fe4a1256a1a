// fleetmap-web: the operator's front door (docs/web-api.md). Parses options, then runs
// WebServer (server/web/http/web_server.h) until SIGTERM or SIGINT.
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <iostream>
#include <map>
#include <thread>

#include <CLI/CLI.hpp>
#include <spdlog/spdlog.h>

#include "app/cli_context.h"
#include "app/exit_codes.h"
#include "app/run_program.h"
#include "protocol/connection.h"
#include "server/core/goal_check.h"
#include "server/web/api/api.h"
#include "server/web/http/web_config.h"
#include "server/web/http/web_server.h"

namespace {
std::atomic<bool> g_stop{false};
extern "C" void on_signal(int) { g_stop = true; }

// FLEETMAP_WEB_HTTP_PORT=0 -> {http_port: 0}: between the config file and the flags.
std::map<std::string, std::string> environment_settings() {
  std::map<std::string, std::string> out;
  for (const char* const* k = fleetmap::web::web_config_keys(); *k; ++k) {
    std::string name = "FLEETMAP_WEB_";
    for (const char* c = *k; *c; ++c) name += static_cast<char>(std::toupper(static_cast<unsigned char>(*c)));
    if (const char* v = std::getenv(name.c_str())) out[*k] = v;
  }
  return out;
}
}  // namespace

int main(int argc, char** argv) {
  using namespace fleetmap;
  using namespace fleetmap::web;
  CLI::App app{"fleetmap-web: the operator's HTTP/WebSocket API and console (docs/web-api.md). People sign in with "
               "their own operator or inspector database account. Settings: the [web] section of the config file "
               "(its user is the read-only web account), FLEETMAP_WEB_<KEY> variables, then the flags below."};
  CliContext ctx(Role::Web);
  ctx.add_connection_options(app);
  std::map<std::string, std::string> flags;
  auto setting = [&](const std::string& flag, const std::string& key, const std::string& type, const std::string& help) {
    app.add_option_function<std::string>(flag, [&flags, key](const std::string& v) { flags[key] = v; }, help)
        ->type_name(type);
  };
  setting("--listen", "listen", "ADDRESS", "address to listen on (default 127.0.0.1)");
  setting("--http-port", "http_port", "PORT", "port (default 8080; 0: any free port, printed on stdout)");
  setting("--tls-cert", "tls_cert", "PEM", "certificate chain: HTTPS and wss (with --tls-key)");
  setting("--tls-key", "tls_key", "PEM", "private key of --tls-cert");
  setting("--static-dir", "static_dir", "DIR", "the console's files (default: server/web/console, or the installed copy)");
  setting("--leaflet-dir", "leaflet_dir", "DIR", "Leaflet, served as /leaflet/ (default /usr/share/javascript/leaflet)");
  setting("--openapi-file", "openapi_file", "FILE", "served as /api/openapi.json (default docs/openapi.json)");
  setting("--threads", "threads", "UINT", "IO threads (default 2)");
  setting("--workers", "workers", "UINT", "threads for database work, each with one read connection (default 4)");
  setting("--feed-period-ms", "feed_period_ms", "MS", "the WebSocket feed's poll period (default 50)");
  setting("--session-idle", "session_idle_s", "SECONDS", "a session ends after this long unused (default 1800)");
  setting("--max-sessions", "max_sessions", "UINT", "sessions open at once (default 256)");
  setting("--max-body-bytes", "max_body_bytes", "BYTES", "larger request bodies get 413 (default 65536)");
  setting("--log-level", "log_level", "LEVEL", "trace, debug, info, warn, error (default info)");
  app.footer("Exit codes: 0 stopped cleanly, 1 failure (database unreachable, port in use), 2 bad setting, 64 usage.");
  return run_program("fleetmap-web", app, argc, argv, [&]() -> int {
    const DbSettings db = ctx.settings();
    WebConfig cfg;
    cfg.static_dir = default_static_dir();
    cfg.openapi_file = default_openapi_file();
    cfg.apply(db.program);
    cfg.apply(environment_settings());
    cfg.apply(flags);
    cfg.check();
    spdlog::set_level(spdlog::level::from_str(cfg.log_level));
    spdlog::set_pattern("%Y-%m-%d %H:%M:%S.%e %^%-5l%$ %v");

    // The read account must work before anyone signs in: exit 1 with connect()'s message.
    connect(db);
    WebServer server(cfg, db, api_routes(), planning_defaults(ctx.config_path()));
    std::signal(SIGTERM, on_signal);
    std::signal(SIGINT, on_signal);
    const unsigned short port = server.start();
    const std::string url = std::string(cfg.tls() ? "https" : "http") + "://" + cfg.listen + ":" + std::to_string(port) + "/";
    std::cout << "fleetmap-web: listening on " << url << std::endl;
    spdlog::info("fleetmap-web listening on {} ({} IO, {} worker threads; read account {}; console {})", url, cfg.threads,
                 cfg.workers, describe(db), cfg.static_dir);
    while (!g_stop) std::this_thread::sleep_for(std::chrono::milliseconds(100));
    spdlog::info("fleetmap-web stopping");
    server.stop();
    spdlog::info("fleetmap-web stopped");
    return exit_code::kOk;
  });
}
