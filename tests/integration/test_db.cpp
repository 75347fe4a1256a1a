#include "tests/integration/test_db.h"

#include <pwd.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "protocol/connection.h"

namespace fleetmap::test {

DbSettings settings(Role role) { return load_settings(role, std::nullopt); }

DbSettings tcp_settings(Role role) {
  DbSettings s = settings(role);
  s.socket.clear();
  s.host = "127.0.0.1";
  return s;
}

std::unique_ptr<mysqlpp::Connection> connect_as(Role role) { return connect(settings(role)); }

std::unique_ptr<mysqlpp::Connection> admin() {
  DbSettings s = settings(Role::Inspector);
  s.user = getpwuid(geteuid())->pw_name;
  s.password.clear();
  return connect(s);
}

long long scalar(const std::string& sql) {
  auto c = admin();
  mysqlpp::Query q = c->query(sql);
  mysqlpp::StoreQueryResult r = q.store();
  if (r.empty() || r[0][0].is_null()) throw std::runtime_error("no value from: " + sql);
  return std::stoll(std::string(r[0][0]));
}

std::string source_path(const std::string& relative) { return std::string(FLEETMAP_SOURCE_DIR) + "/" + relative; }
std::string real_map(const std::string& file) { return std::string(FLEETMAP_REAL_MAPS) + "/" + file; }

std::string instance_home() {
  // The fixture's instance folder holds its fleetmap.conf (FLEETMAP_CONFIG).
  const char* conf = std::getenv("FLEETMAP_CONFIG");
  if (!conf) throw std::runtime_error("FLEETMAP_CONFIG is not set: run the integration tests through ctest");
  return std::filesystem::path(conf).parent_path().string();
}

void once_per_instance(const std::string& key, const std::function<void()>& setup) {
  const std::string marker = temp_path("once." + key);
  if (std::filesystem::exists(marker)) return;
  setup();
  write_file(marker, "done\n");
}

std::string db_script() {
  // The options the fixture started the instance with (tests/CMakeLists.txt).
  return "FLEETMAP_HOME=" + instance_home() + " FLEETMAP_PORT=" + std::to_string(settings(Role::Inspector).port) +
         " FLEETMAP_MYSQLD_ARGS='" FLEETMAP_TEST_DB_MYSQLD_ARGS "' bash " + source_path("scripts/db.sh");
}

std::string temp_path(const std::string& name) {
  const std::filesystem::path dir = std::filesystem::path(instance_home()) / "scratch";
  std::filesystem::create_directories(dir);
  return (dir / name).string();
}

void write_file(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::string read_file_once_it_has(const std::string& path, const std::string& needle) {
  std::string text;
  wait_until([&] {
    text = read_file(path);
    return text.find(needle) != std::string::npos;
  }, std::chrono::seconds(5));
  return text;
}

std::map<std::string, std::string> yaml_fields(const std::string& text) {
  std::map<std::string, std::string> kv;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line))
    if (size_t c = line.find(": "); c != std::string::npos) kv[line.substr(0, c)] = line.substr(c + 2);
  return kv;
}

RunResult run(const std::string& program, const std::string& args) {
  const std::string out = temp_path("run.out"), err = temp_path("run.err");
  const std::string cmd = std::string(FLEETMAP_BIN_DIR) + "/" + program + " " + args + " >" + out + " 2>" + err;
  const int status = std::system(cmd.c_str());
  RunResult r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = read_file(out);
  r.err = read_file(err);
  return r;
}

}  // namespace fleetmap::test
