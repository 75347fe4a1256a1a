#pragma once
// Runs the built programs (FLEETMAP_BIN_DIR) the way a person would, with no database:
// no FLEETMAP_* variables and a scratch working directory, so no config file is found.
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace fleetmap::test {

struct CliResult {
  int exit_code = -1;
  std::string out, err;
};

inline std::string scratch_dir() {
  static const std::string dir = [] {
    auto d = std::filesystem::temp_directory_path() / ("fleetmap-cli-test-" + std::to_string(getpid()));
    std::filesystem::create_directories(d);
    return d.string();
  }();
  return dir;
}

inline std::string scratch_file(const std::string& name) { return scratch_dir() + "/" + name; }

inline std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

inline void spit(const std::string& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

inline std::string repo_path(const std::string& relative) { return std::string(FLEETMAP_SOURCE_DIR) + "/" + relative; }

// program: "fleetmap", "fleetmap-server" or "fleetmap-robot"; args: shell-quoted.
inline CliResult run_cli(const std::string& program, const std::string& args) {
  const std::string out = scratch_file("cli.out"), err = scratch_file("cli.err");
  const std::string cmd = "cd '" + scratch_dir() +
                          "' && env -u FLEETMAP_CONFIG -u FLEETMAP_HOME -u FLEETMAP_HOST -u FLEETMAP_PORT "
                          "-u FLEETMAP_SOCKET -u FLEETMAP_DB -u FLEETMAP_USER -u FLEETMAP_PASSWORD " +
                          std::string(FLEETMAP_BIN_DIR) + "/" + program + " " + args + " >'" + out + "' 2>'" + err +
                          "' </dev/null";
  const int status = std::system(cmd.c_str());
  CliResult r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = slurp(out);
  r.err = slurp(err);
  return r;
}

}  // namespace fleetmap::test
