#include "server/web/http/web_config.h"

#include <filesystem>
#include <stdexcept>

#include "app/config_number.h"

namespace fleetmap::web {
namespace {

size_t whole(const std::string& key, const std::string& v, double least, double most) {
  return config_whole("[web]", key, v, least, most);
}

// Where a file of the source tree is, else where CMake installs it.
std::string source_or_installed(const std::string& source, const std::string& installed) {
  if (std::filesystem::exists(source)) return source;
  return installed;
}

constexpr const char* kKeys[] = {"listen",  "http_port", "tls_cert",       "tls_key",        "static_dir",
                                 "leaflet_dir", "openapi_file", "threads",   "workers",        "feed_period_ms",
                                 "session_idle_s", "max_sessions", "max_body_bytes", "log_level", nullptr};

}  // namespace

const char* const* web_config_keys() { return kKeys; }

void WebConfig::apply(const std::map<std::string, std::string>& s) {
  for (const auto& [k, v] : s) {
    if (k == "listen") listen = v;
    else if (k == "http_port") http_port = static_cast<unsigned>(whole(k, v, 0, 65535));
    else if (k == "tls_cert") tls_cert = v;
    else if (k == "tls_key") tls_key = v;
    else if (k == "static_dir") static_dir = v;
    else if (k == "leaflet_dir") leaflet_dir = v;
    else if (k == "openapi_file") openapi_file = v;
    else if (k == "threads") threads = static_cast<int>(whole(k, v, 1, 64));
    else if (k == "workers") workers = static_cast<int>(whole(k, v, 1, 256));
    else if (k == "feed_period_ms") feed_period_ms = static_cast<int>(whole(k, v, 5, 60000));
    else if (k == "session_idle_s") session_idle_s = static_cast<int>(whole(k, v, 1, 7 * 86400));
    else if (k == "max_sessions") max_sessions = whole(k, v, 1, 1e6);
    else if (k == "max_body_bytes") max_body_bytes = whole(k, v, 16, 1u << 30);
    else if (k == "log_level") {
      if (v != "trace" && v != "debug" && v != "info" && v != "warn" && v != "error" && v != "critical" && v != "off")
        throw std::invalid_argument("[web] log_level: expected trace, debug, info, warn or error, got '" + v + "'");
      log_level = v;
    } else
      throw std::invalid_argument("[web] unknown setting '" + k + "'");
  }
}

void WebConfig::check() const {
  if (tls_cert.empty() != tls_key.empty())
    throw std::invalid_argument("[web] tls_cert and tls_key: give both (HTTPS) or neither (HTTP)");
}

std::string default_static_dir() {
  return source_or_installed(FLEETMAP_WEB_SOURCE_DIR "/server/web/console", FLEETMAP_WEB_SHARE_DIR "/console");
}

std::string default_openapi_file() {
  return source_or_installed(FLEETMAP_WEB_SOURCE_DIR "/docs/openapi.json", FLEETMAP_WEB_SHARE_DIR "/openapi.json");
}

}  // namespace fleetmap::web
