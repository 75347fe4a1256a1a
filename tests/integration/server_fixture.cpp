#include "tests/integration/server_fixture.h"

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <stdexcept>
#include <thread>

#include "tests/integration/test_db.h"

namespace fleetmap::test {

namespace {

pid_t spawn_shell(const std::string& cmd) {
  const pid_t pid = fork();
  if (pid == 0) {
    execl("/bin/sh", "sh", "-c", cmd.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  if (pid < 0) throw std::runtime_error("fork failed");
  return pid;
}

void terminate_and_wait(pid_t pid) {
  ::kill(pid, SIGTERM);
  int status = 0;
  waitpid(pid, &status, 0);
}

}  // namespace

pid_t spawn_server(const std::string& flags, const std::string& log_path) {
  return spawn_shell("exec " + std::string(FLEETMAP_BIN_DIR) + "/fleetmap-server --log-level debug " + flags + " >>" +
                     log_path + " 2>&1");
}

RobotSimProcess::RobotSimProcess(const std::string& name, const std::string& flags)
    : log_path_(temp_path(name + ".log")) {
  pid_ = spawn_shell("exec " + std::string(FLEETMAP_BIN_DIR) + "/fleetmap-robot --config " +
                     std::getenv("FLEETMAP_CONFIG") + " --user " + name + " --password-file " +
                     temp_path(name + ".pw") + " " + flags + " >" + log_path_ + " 2>&1");
}

RobotSimProcess::~RobotSimProcess() { terminate_and_wait(pid_); }

std::string RobotSimProcess::log() const { return read_file(log_path_); }

ServerProcess::ServerProcess(const std::string& flags, const std::string& log_name)
    : log_path_(temp_path(log_name)), pid_(spawn_server(flags, log_path_)) {}

ServerProcess::~ServerProcess() {
  if (pid_ > 0) terminate();
}

void ServerProcess::terminate() {
  if (pid_ <= 0) return;
  terminate_and_wait(pid_);
  pid_ = -1;
}

void ServerProcess::kill9() {
  if (pid_ <= 0) return;
  ::kill(pid_, SIGKILL);
  int status = 0;
  waitpid(pid_, &status, 0);
  pid_ = -1;
}

std::string ServerProcess::log() const { return read_file(log_path_); }

bool import_real_map_once(const std::string& name, const std::string& file) {
  auto db = admin();  // the query uses the connection: keep it open
  mysqlpp::Query exists = db->query();
  exists << "SELECT COUNT(*) FROM maps WHERE name = " << mysqlpp::quote << name;
  if (std::stoll(std::string(exists.store()[0][0])) > 0) return true;
  return run("fleetmap", "map import " + real_map(file) + " --name " + name).exit_code == 0;
}

std::string add_robot(const std::string& name, const std::string& map) {
  const std::string password = "pw-" + name + "-0123456789";
  const std::string pw_file = temp_path(name + ".pw");
  write_file(pw_file, password + "\n");
  run("fleetmap", "robot remove " + name);  // a robot from an earlier run
  RunResult r = run("fleetmap", "robot add " + name + " --map " + map + " --password-file " + pw_file);
  if (r.exit_code != 0) throw std::runtime_error("robot add " + name + ": " + r.err);
  return password;
}

std::vector<std::string> add_robots(const std::vector<std::string>& names, const std::string& map) {
  auto db = admin();
  std::vector<std::string> passwords;
  for (const std::string& name : names) {
    passwords.push_back("pw-" + name + "-0123456789");
    mysqlpp::Query exists = db->query();
    exists << "SELECT COUNT(*) FROM robots WHERE removed_at IS NULL AND db_user = " << mysqlpp::quote << name;
    if (std::stoll(std::string(exists.store()[0][0])) > 0) {  // a robot from an earlier run
      mysqlpp::Query remove = db->query();
      remove << "CALL robot_remove(" << mysqlpp::quote << name << ")";
      remove.execute();
    }
    mysqlpp::Query add = db->query();
    add << "CALL robot_add(" << mysqlpp::quote << name << ", " << mysqlpp::quote << passwords.back() << ", "
        << mysqlpp::quote << map << ", NULL)";
    add.execute();
  }
  return passwords;
}

RemoveRobotsAtEnd::~RemoveRobotsAtEnd() {
  for (const std::string& n : names) run("fleetmap", "robot remove " + n);
}

void ensure_example_map(const std::string& name) {
  if (scalar("SELECT COUNT(*) FROM maps WHERE name = '" + name + "'") > 0) return;
  RunResult r = run("fleetmap", "map import " + source_path("maps/example-campus.map") + " --name " + name);
  if (r.exit_code != 0) throw std::runtime_error("map import: " + r.err);
}

SqlRobot::SqlRobot(const std::string& name, const std::string& password) {
  DbSettings s = tcp_settings(Role::Inspector);  // host, port, database of the instance
  c_ = std::make_unique<mysqlpp::Connection>(true);
  c_->set_option(new mysqlpp::SetCharsetNameOption("utf8mb4"));
  c_->connect(s.database.c_str(), s.host.c_str(), name.c_str(), password.c_str(), s.port);
}

unsigned long long SqlRobot::send(const std::string& op, const std::string& params_json,
                                  const std::optional<std::string>& payload, std::optional<unsigned> robot_id) {
  mysqlpp::Query q = c_->query();
  q << "INSERT INTO rr (robot_id, op, params, payload) VALUES ("
    << (robot_id ? std::to_string(*robot_id) : "NULL") << ", " << mysqlpp::quote << op << ", " << mysqlpp::quote
    << params_json << ", ";
  if (payload) q << mysqlpp::quote << *payload;
  else q << "NULL";
  q << ")";
  q.execute();
  mysqlpp::Query id = c_->query("SELECT LAST_INSERT_ID()");
  return std::stoull(std::string(id.store()[0][0]));
}

std::vector<SqlAnswer> SqlRobot::peek() {
  mysqlpp::Query q = c_->query("SELECT id, robot_id, request_id, op, params, payload FROM sa_mine ORDER BY id");
  std::vector<SqlAnswer> out;
  for (const mysqlpp::Row& r : q.store()) {
    SqlAnswer a;
    a.id = std::stoull(std::string(r[0]));
    a.robot_id = static_cast<unsigned>(std::stoul(std::string(r[1])));
    if (!r[2].is_null()) a.request_id = std::stoull(std::string(r[2]));
    a.op = std::string(r[3]);
    a.params = nlohmann::json::parse(std::string(r[4]));
    if (!r[5].is_null()) a.payload = std::string(r[5].data(), r[5].length());
    out.push_back(std::move(a));
  }
  return out;
}

std::vector<SqlAnswer> SqlRobot::receive(size_t n, std::chrono::milliseconds timeout) {
  std::vector<SqlAnswer> got;
  const auto until = std::chrono::steady_clock::now() + timeout;
  while (got.size() < n && std::chrono::steady_clock::now() < until) {
    for (SqlAnswer& a : peek()) {
      if (got.size() >= n) break;
      mysqlpp::Query d = c_->query();
      d << "DELETE FROM sa_mine WHERE id = " << a.id;
      d.execute();
      got.push_back(std::move(a));
    }
    if (got.size() < n) std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return got;
}

}  // namespace fleetmap::test
