// What the programs say when they cannot reach a database (README "Exit codes": 1), with
// no database at all: no config file found, a socket that is not there (the server is
// down), a port nothing listens on; and a config file whose values carry trailing
// comments, read by the real programs.
#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>

#include <filesystem>

#include <gtest/gtest.h>

#include "tests/server/cli/cli_run.h"

namespace fleetmap::test {
namespace {

// A loopback port nobody listens on: bound, read and closed again.
unsigned free_port() {
  const int fd = socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  socklen_t len = sizeof a;
  bind(fd, reinterpret_cast<sockaddr*>(&a), sizeof a);
  getsockname(fd, reinterpret_cast<sockaddr*>(&a), &len);
  close(fd);
  return ntohs(a.sin_port);
}

std::string config_file(const std::string& name, const std::string& database_section) {
  const std::string path = scratch_file(name);
  spit(path, "[database]\n" + database_section +
                 "name = fleetmap          # the database\n"
                 "[operator]\nuser = fleetmap_operator   # the operator's account\npassword = secret # not really\n"
                 "[server]\nuser = fleetmap_server\npassword = s\n"
                 "alive_period_s = 2            # told to robots in Start\n");
  return path;
}

TEST(DatabaseErrors, NoConfigFileFoundSaysWhereItLookedAndExits1) {
  if (std::filesystem::exists("/etc/fleetmap/fleetmap.conf")) GTEST_SKIP() << "this machine has a system config";
  for (const char* program : {"fleetmap", "fleetmap-server"}) {
    const CliResult r = run_cli(program, std::string(program) == "fleetmap" ? "robots" : "");
    EXPECT_EQ(r.exit_code, 1) << program << ": " << r.err;
    EXPECT_NE(r.err.find("no config file found (looked for --config FILE, $FLEETMAP_CONFIG"), std::string::npos)
        << program << ": " << r.err;
    EXPECT_NE(r.err.find("scripts/db.sh start"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("root"), std::string::npos) << r.err;
  }
}

TEST(DatabaseErrors, AMissingSocketMeansTheServerIsNotRunning) {
  const std::string socket = scratch_file("no-such.sock");
  const std::string conf = config_file("socket.conf", "socket = " + socket + "   # the private instance\n");
  const CliResult r = run_cli("fleetmap", "robots --config " + conf);
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find("the socket " + socket + " does not exist: the database server is not running"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(r.err.find("Bad character"), std::string::npos) << r.err;
}

TEST(DatabaseErrors, APortNobodyListensOnSaysTheServerIsNotListening) {
  const unsigned port = free_port();
  const std::string conf =
      config_file("tcp.conf", "host = 127.0.0.1   # loopback\nport = " + std::to_string(port) + "   # nobody\n");
  const CliResult r = run_cli("fleetmap", "--config " + conf + " tasks");
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find("cannot connect as fleetmap_operator@127.0.0.1:" + std::to_string(port) + "/fleetmap"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("not running or not listening there"), std::string::npos) << r.err;
  // The server's --check says the same, with the [server] section's trailing comments read.
  const CliResult s = run_cli("fleetmap-server", "--check --config " + conf);
  EXPECT_EQ(s.exit_code, 1) << s.err;
  EXPECT_NE(s.err.find("not running or not listening there"), std::string::npos) << s.err;
}

TEST(DatabaseErrors, ATrailingCommentIsNotPartOfABadValue) {
  const std::string conf = scratch_file("bad-value.conf");
  spit(conf, "[database]\nsocket = /nowhere.sock\n[server]\nuser = s\nalive_period_s = abc   # told to robots\n");
  const CliResult r = run_cli("fleetmap-server", "--check --config " + conf);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("alive_period_s: expected a positive number, got 'abc'"), std::string::npos) << r.err;
}

TEST(DatabaseErrors, TheServerLogsADeadDatabaseOncePerBackOffStep) {
  const std::string conf =
      config_file("dead.conf", "host = 127.0.0.1\nport = " + std::to_string(free_port()) + "\n");
  const std::string log = scratch_file("dead-server.log");
  // 1.5 s of a dead database, two workers and the stall guard trying: lines at 0, then
  // after 0.1, 0.2, 0.4 and 0.8 s steps (server/daemon/database_outage.h), at 0.1, 0.3,
  // 0.7 and 1.5 s: at most five; one per thread and attempt would be well over twenty.
  const std::string cmd = "cd '" + scratch_dir() + "' && timeout -k 10 1.5 " + std::string(FLEETMAP_BIN_DIR) +
                          "/fleetmap-server --workers 2 --config " + conf + " >'" + log + "' 2>&1";
  const int status = std::system(cmd.c_str());
  ASSERT_TRUE(WIFEXITED(status)) << status;
  const std::string text = slurp(log);
  size_t lines = 0;
  for (size_t at = text.find("not listening there"); at != std::string::npos; at = text.find("not listening there", at + 1))
    ++lines;
  EXPECT_GE(lines, 2u) << text;
  EXPECT_LE(lines, 5u) << text;
}

}  // namespace
}  // namespace fleetmap::test
