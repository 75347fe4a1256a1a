#pragma once
// Where and as whom a program connects (SPEC 4): one config file, overridden by
// FLEETMAP_* environment variables, overridden by command-line flags.
//
//   [database]             [server] / [operator] / [inspector] / [web]
//   host = 127.0.0.1       user = fleetmap_operator
//   port = 33306           password = ...
//   socket = /path/sock    (or password_file = /path)
//   name = fleetmap
//   hosts = db1:3306, db2, db3:3307   (robots: the nodes of a Galera cluster to fail over
//                                      between, in order; a host without :port has `port`)
//
// Comments: a line starting with '#' or ';', and the rest of a line from a '#' that
// follows a space or tab ("port = 33306   # loopback").
//
// Environment: FLEETMAP_CONFIG (the file), FLEETMAP_HOST, FLEETMAP_PORT, FLEETMAP_SOCKET,
// FLEETMAP_DB, FLEETMAP_USER, FLEETMAP_PASSWORD, FLEETMAP_HOSTS. See etc/fleetmap.conf.sample.
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace fleetmap {

enum class Role { Server, Operator, Inspector, Robot, Web };

// One database node to connect to over TCP; port 0: the settings' port.
struct DbEndpoint {
  std::string host;
  unsigned port = 0;
  bool operator==(const DbEndpoint&) const = default;
};

// "db1:3306, db2, [::1]:3307": comma-separated hosts, each with an optional :port.
// Throws BadInput naming `where` and the entry on an empty list, an empty entry or a bad port.
std::vector<DbEndpoint> parse_hosts(const std::string& text, const std::string& where);
const char* section_name(Role role);

struct DbSettings {
  std::string host = "127.0.0.1";
  unsigned port = 33306;
  std::string socket;  // preferred over host:port when set
  // Failover list (RobotClient): when not empty, these instead of host:port, tried in order.
  std::vector<DbEndpoint> hosts;
  std::string database = "fleetmap";
  std::string user;
  std::string password;
  std::string source;  // which config file was read, for messages
  std::string section;  // the role's section ("operator"), for messages
  // Other keys of the role's section: settings of the program itself (e.g. the server's
  // alive_period_s), read by that program.
  std::map<std::string, std::string> program;
};

// The config file to read: FLEETMAP_CONFIG, else $FLEETMAP_HOME/fleetmap.conf, else
// ./.fleetmap/fleetmap.conf, else /etc/fleetmap/fleetmap.conf; nullopt when none exists.
std::optional<std::string> find_config_file();

// Where find_config_file looks, in order, for messages.
std::string config_search_path();

// Defaults, then the file's [database] and [role] sections (an explicit path must exist),
// then the environment. Throws std::runtime_error naming the file and line on a bad file.
DbSettings load_settings(Role role, const std::optional<std::string>& config_path);

// Parses one config text into settings for a role (exposed for tests). Without
// read_password_files a password_file is not opened (its password is left empty).
void apply_config_text(DbSettings& s, Role role, const std::string& text, const std::string& file,
                       bool read_password_files = true);

// The program settings of a role's section of this file (the server's robot_radius_m,
// as `fleetmap goal` plans with it), without its account: another role's password file
// need not be readable. Throws like load_settings for a bad file.
std::map<std::string, std::string> program_settings(Role role, const std::string& config_path);
void apply_environment(DbSettings& s);

// The nodes to try, in order: hosts with their ports filled in, else host:port alone.
std::vector<DbEndpoint> endpoints(const DbSettings& s);

}  // namespace fleetmap
