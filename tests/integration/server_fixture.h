#pragma once
// For tests of the server: the real fleetmap-server as a child process, robot accounts
// made with the real `fleetmap robot add`, and SqlRobot, a reference robot that speaks
// the protocol with plain SQL statements only (no project code on its side).
#include <sys/types.h>

#include <chrono>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <mysql++/mysql++.h>
#include <nlohmann/json.hpp>

namespace fleetmap::test {

// Forks build/bin/fleetmap-server --log-level debug FLAGS, its output appended to
// log_path; returns the child's pid.
pid_t spawn_server(const std::string& flags, const std::string& log_path);

// Flags for a server whose test robot sends nothing between the test's steps: Alive every
// 0.5 s, yet lost only after a minute of silence, since a step may be a sanitized CLI run
// on a loaded machine (a GetPath test once saw its robot lost and its task failed).
inline constexpr const char* kQuietRobotFlags = "--alive-period 0.5 --lost-after 120";

class ServerProcess {
 public:
  // Starts build/bin/fleetmap-server with extra flags; its log goes to a scratch file.
  explicit ServerProcess(const std::string& flags = "", const std::string& log_name = "server.log");
  ~ServerProcess();  // SIGTERM, then waits
  void terminate();  // SIGTERM and wait; returns when it exited
  void kill9();      // SIGKILL and wait
  bool running() const { return pid_ > 0; }
  std::string log() const;
  ServerProcess(const ServerProcess&) = delete;
  ServerProcess& operator=(const ServerProcess&) = delete;

 private:
  std::string log_path_;  // before pid_: the constructor starts the process with it
  pid_t pid_ = -1;
};

// A simulated robot: build/bin/fleetmap-robot --config $FLEETMAP_CONFIG --user NAME
// --password-file <scratch>/NAME.pw FLAGS, its output in <scratch>/NAME.log (replaced).
class RobotSimProcess {
 public:
  RobotSimProcess(const std::string& name, const std::string& flags);
  ~RobotSimProcess();  // SIGTERM, then waits
  std::string log() const;
  RobotSimProcess(const RobotSimProcess&) = delete;
  RobotSimProcess& operator=(const RobotSimProcess&) = delete;

 private:
  std::string log_path_;
  pid_t pid_ = -1;
};

// Imports the real map FLEETMAP_REAL_MAPS/file as `name` (fleetmap map import) unless a
// map of that name exists: the suites of one instance share it. False when the import fails.
bool import_real_map_once(const std::string& name, const std::string& file);
// Creates (or re-creates) a robot account on map via the real CLI; returns its password,
// which it also writes to <scratch>/NAME.pw (where RobotSimProcess reads it).
std::string add_robot(const std::string& name, const std::string& map);
// Many accounts at once (a fleet): the account procedures of sql/40_robot_accounts.sql,
// which `robot add` calls, on one connection instead of two CLI processes per robot.
// Returns the passwords, in the order of names.
std::vector<std::string> add_robots(const std::vector<std::string>& names, const std::string& map);
// Removes the robots (fleetmap robot remove) when it goes out of scope.
struct RemoveRobotsAtEnd {
  std::vector<std::string> names;
  ~RemoveRobotsAtEnd();
};
// Imports maps/example-campus.map as `name` if it is not there yet.
void ensure_example_map(const std::string& name);

struct SqlAnswer {
  unsigned long long id = 0;
  unsigned robot_id = 0;
  std::optional<unsigned long long> request_id;
  std::string op;
  nlohmann::json params;
  std::optional<std::string> payload;
};

class SqlRobot {
 public:
  SqlRobot(const std::string& name, const std::string& password);
  mysqlpp::Connection& connection() { return *c_; }

  // INSERT INTO rr; returns the request id (LAST_INSERT_ID()).
  unsigned long long send(const std::string& op, const std::string& params_json = "{}",
                          const std::optional<std::string>& payload = std::nullopt,
                          std::optional<unsigned> robot_id = std::nullopt);
  // Reads sa_mine in id order until n answers arrived (or the timeout), deleting each.
  std::vector<SqlAnswer> receive(size_t n, std::chrono::milliseconds timeout = std::chrono::seconds(10));
  // Everything in sa_mine now, without deleting.
  std::vector<SqlAnswer> peek();

 private:
  std::unique_ptr<mysqlpp::Connection> c_;
};

}  // namespace fleetmap::test
