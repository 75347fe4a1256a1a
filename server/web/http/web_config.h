#pragma once
// fleetmap-web's own settings (docs/web-api.md): defaults, then the [web] section of the
// config file (whose user/password are the read account, SPEC 4), then FLEETMAP_WEB_*
// environment variables, then flags (web_main.cpp). Documented in etc/fleetmap.conf.sample.
#include <cstddef>
#include <map>
#include <string>

namespace fleetmap::web {

struct WebConfig {
  std::string listen = "127.0.0.1";
  unsigned http_port = 8080;  // 0: any free port, printed on stdout
  std::string tls_cert, tls_key;  // both or neither: HTTPS and wss
  std::string static_dir;    // the console; default: default_static_dir()
  std::string leaflet_dir = "/usr/share/javascript/leaflet";
  std::string openapi_file;  // default: default_openapi_file()
  int threads = 2;           // IO threads
  int workers = 4;           // threads for handler work (anything touching MySQL)
  int feed_period_ms = 50;   // the WebSocket feed's poll period
  int session_idle_s = 1800;
  size_t max_sessions = 256;
  size_t max_body_bytes = 65536;
  std::string log_level = "info";

  bool tls() const { return !tls_cert.empty(); }

  // Applies "key = value" settings; throws std::invalid_argument naming a bad key or
  // value. Keys that are not the web program's (the account's user, password,
  // password_file) are left to protocol/db_settings.h.
  void apply(const std::map<std::string, std::string>& settings);
  // Throws std::invalid_argument when the settings do not fit together (one of
  // tls_cert/tls_key without the other).
  void check() const;
};

// The keys apply() knows, for FLEETMAP_WEB_<KEY> environment overrides.
const char* const* web_config_keys();

// The console's folder: server/web/console of the source tree when it is there, else
// the installed share/fleetmap/console.
std::string default_static_dir();
// docs/openapi.json likewise (installed as share/fleetmap/openapi.json).
std::string default_openapi_file();

}  // namespace fleetmap::web
