#pragma once
// Shared by the integration tests: the private MariaDB started by the CTest fixture
// (scripts/db.sh start with FLEETMAP_HOME/FLEETMAP_PORT from tests/CMakeLists.txt),
// its accounts, and running the real programs.
#include <chrono>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <thread>

#include <mysql++/mysql++.h>

#include "protocol/db_settings.h"

namespace fleetmap::test {

// Settings of one of the instance's accounts, from its fleetmap.conf.
DbSettings settings(Role role);

// Over TCP (127.0.0.1), as a robot or GIS tool would connect.
DbSettings tcp_settings(Role role);

std::unique_ptr<mysqlpp::Connection> connect_as(Role role);

// The instance's administrator: the OS user over the unix socket (scripts/db.sh).
std::unique_ptr<mysqlpp::Connection> admin();

// One number from a query run as administrator.
long long scalar(const std::string& sql);

// Polls pred until it holds (true) or the timeout passes (false).
template <class Pred>
bool wait_until(Pred pred, std::chrono::milliseconds timeout = std::chrono::seconds(10),
                std::chrono::milliseconds step = std::chrono::milliseconds(20)) {
  const auto until = std::chrono::steady_clock::now() + timeout;
  while (!pred()) {
    if (std::chrono::steady_clock::now() >= until) return false;
    std::this_thread::sleep_for(step);
  }
  return true;
}

struct RunResult {
  int exit_code = -1;
  std::string out;
  std::string err;
};

// Runs build/bin/<program> with args (a shell-quoted string), capturing both streams.
RunResult run(const std::string& program, const std::string& args);

std::string source_path(const std::string& relative);  // under the checkout
std::string real_map(const std::string& file);         // FLEETMAP_REAL_MAPS/<file>
std::string temp_path(const std::string& name);        // a scratch file for this test run
std::string instance_home();                           // the test instance's folder
// Runs setup the first time `key` is asked for on this instance, and never again while
// the instance lives (a marker in its scratch folder, written once setup returned).
// CTest runs each test in a process of its own, so a suite's SetUpTestSuite would
// otherwise import the same maps once per test.
void once_per_instance(const std::string& key, const std::function<void()>& setup);
std::string db_script();                               // "FLEETMAP_HOME=... FLEETMAP_PORT=... bash scripts/db.sh"
void write_file(const std::string& path, const std::string& text);
std::string read_file(const std::string& path);
// The file once it contains needle, or as it is after 5 s. A server logs what it did after
// doing it (the stall guard: after its KILL returns), so a test that saw the effect
// can read the file before the line is there.
std::string read_file_once_it_has(const std::string& path, const std::string& needle);
// The "key: value" lines of a flat YAML text (a Nav2 map .yaml).
std::map<std::string, std::string> yaml_fields(const std::string& text);

}  // namespace fleetmap::test
