#include "protocol/db_settings.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "common/core/error.h"

namespace fleetmap {
namespace {

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
}

// A '#' after a space or tab starts a comment, as the sample file writes them
// ("port = 33306   # loopback"); a '#' inside a word stays (a password "pa#ss"), so a
// value that must hold " #" goes into a password_file.
std::string strip_comment(const std::string& line) {
  for (size_t i = 1; i < line.size(); ++i)
    if (line[i] == '#' && (line[i - 1] == ' ' || line[i - 1] == '\t')) return trim(line.substr(0, i));
  return line;
}

unsigned parse_port(const std::string& v, const std::string& where) {
  try {
    size_t used = 0;
    const unsigned long p = std::stoul(v, &used);
    if (used == v.size() && p > 0 && p < 65536) return static_cast<unsigned>(p);
  } catch (const std::exception&) {
  }
  throw BadInput(where + ": expected a port number 1..65535, got '" + v + "'");
}

}  // namespace

std::vector<DbEndpoint> parse_hosts(const std::string& text, const std::string& where) {
  std::vector<DbEndpoint> out;
  const auto bad = [&](const std::string& why) {
    return BadInput(where + ": expected hosts as 'host[:port], host[:port], ...', got '" + text + "' (" + why + ")");
  };
  size_t at = 0;
  while (at <= text.size()) {
    const size_t comma = std::min(text.find(',', at), text.size());
    const std::string entry = trim(text.substr(at, comma - at));
    at = comma + 1;
    if (entry.empty()) throw bad("an empty entry");
    DbEndpoint e;
    // [v6]:port, host:port, or a host alone (a bare IPv6 address has several ':').
    std::string port;
    if (entry.front() == '[') {
      const size_t close = entry.find(']');
      if (close == std::string::npos) throw bad("'" + entry + "' has no closing ']'");
      e.host = entry.substr(1, close - 1);
      const std::string rest = entry.substr(close + 1);
      if (!rest.empty() && rest.front() != ':') throw bad("'" + entry + "': expected ':port' after ']'");
      if (!rest.empty()) port = rest.substr(1);
    } else if (const size_t colon = entry.rfind(':'); colon != std::string::npos && entry.find(':') == colon) {
      e.host = trim(entry.substr(0, colon));
      port = trim(entry.substr(colon + 1));
    } else {
      e.host = entry;
    }
    if (e.host.empty()) throw bad("'" + entry + "' has no host");
    if (e.host.find_first_of(" \t") != std::string::npos) throw bad("'" + entry + "': a host has no spaces");
    if (!port.empty() || (entry.back() == ':')) {
      try {
        e.port = parse_port(port, where);
      } catch (const BadInput&) {
        throw bad("'" + entry + "': the port must be 1..65535");
      }
    }
    out.push_back(std::move(e));
    if (comma == text.size()) break;
  }
  return out;
}

std::vector<DbEndpoint> endpoints(const DbSettings& s) {
  if (s.hosts.empty()) return {DbEndpoint{s.host, s.port}};
  std::vector<DbEndpoint> out = s.hosts;
  for (DbEndpoint& e : out)
    if (e.port == 0) e.port = s.port;
  return out;
}

namespace {

std::string read_file(const std::string& path, const std::string& what) {
  std::ifstream in(path);
  if (!in) throw IoError("cannot read " + what + " '" + path + "'");
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

const char* env(const char* name) {
  const char* v = std::getenv(name);
  return (v && *v) ? v : nullptr;
}

}  // namespace

const char* section_name(Role role) {
  switch (role) {
    case Role::Server: return "server";
    case Role::Operator: return "operator";
    case Role::Inspector: return "inspector";
    case Role::Robot: return "robot";
    case Role::Web: return "web";
  }
  return "";
}

std::optional<std::string> find_config_file() {
  namespace fs = std::filesystem;
  if (const char* c = env("FLEETMAP_CONFIG")) return std::string(c);
  if (const char* h = env("FLEETMAP_HOME"))
    if (fs::exists(fs::path(h) / "fleetmap.conf")) return (fs::path(h) / "fleetmap.conf").string();
  for (const char* p : {".fleetmap/fleetmap.conf", "/etc/fleetmap/fleetmap.conf"})
    if (fs::exists(p)) return std::string(p);
  return std::nullopt;
}

std::string config_search_path() {
  return "--config FILE, $FLEETMAP_CONFIG, $FLEETMAP_HOME/fleetmap.conf, ./.fleetmap/fleetmap.conf, "
         "/etc/fleetmap/fleetmap.conf";
}

void apply_config_text(DbSettings& s, Role role, const std::string& text, const std::string& file,
                       bool read_password_files) {
  std::istringstream in(text);
  std::string line, section;
  size_t no = 0;
  const std::string mine = section_name(role);
  while (std::getline(in, line)) {
    ++no;
    const std::string where = file + ":" + std::to_string(no);
    line = trim(line);
    if (line.empty() || line[0] == '#' || line[0] == ';') continue;
    line = strip_comment(line);
    if (line.front() == '[') {
      if (line.back() != ']') throw FileFormatError(where + ": expected '[section]', got '" + line + "'");
      section = trim(line.substr(1, line.size() - 2));
      continue;
    }
    const auto eq = line.find('=');
    if (eq == std::string::npos) throw FileFormatError(where + ": expected 'key = value', got '" + line + "'");
    const std::string key = trim(line.substr(0, eq)), value = trim(line.substr(eq + 1));
    if (section == "database") {
      if (key == "host") s.host = value;
      else if (key == "port") s.port = parse_port(value, where);
      else if (key == "socket") s.socket = value;
      else if (key == "name") s.database = value;
      else if (key == "hosts") s.hosts = parse_hosts(value, where + ": hosts");
      else throw FileFormatError(where + ": expected host, port, socket, name or hosts in [database], got '" + key + "'");
    } else if (section == mine) {
      if (key == "user") s.user = value;
      else if (key == "password") s.password = value;
      else if (key == "password_file") s.password = read_password_files ? trim(read_file(value, "password file")) : "";
      else s.program[key] = value;  // the program's own settings
    }
  }
  s.source = file;
}

void apply_environment(DbSettings& s) {
  if (const char* v = env("FLEETMAP_HOST")) s.host = v;
  if (const char* v = env("FLEETMAP_PORT")) s.port = parse_port(v, "FLEETMAP_PORT");
  if (const char* v = env("FLEETMAP_SOCKET")) s.socket = v;
  if (const char* v = env("FLEETMAP_DB")) s.database = v;
  if (const char* v = env("FLEETMAP_USER")) s.user = v;
  if (const char* v = env("FLEETMAP_PASSWORD")) s.password = v;
  if (const char* v = env("FLEETMAP_HOSTS")) s.hosts = parse_hosts(v, "FLEETMAP_HOSTS");
}

std::map<std::string, std::string> program_settings(Role role, const std::string& config_path) {
  DbSettings s;
  apply_config_text(s, role, read_file(config_path, "config file"), config_path, false);
  return s.program;
}

DbSettings load_settings(Role role, const std::optional<std::string>& config_path) {
  DbSettings s;
  s.section = section_name(role);
  const std::optional<std::string> path = config_path ? config_path : find_config_file();
  if (path) apply_config_text(s, role, read_file(*path, "config file"), *path);
  apply_environment(s);
  return s;
}

}  // namespace fleetmap
