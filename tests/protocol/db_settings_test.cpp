// Config text (protocol/db_settings.h): sections, comments on their own lines and after
// values, as etc/fleetmap.conf.sample writes them, and malformed lines named by line.
#include "protocol/db_settings.h"

#include <unistd.h>

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "common/core/error.h"

namespace fleetmap {
namespace {

DbSettings parse(Role role, const std::string& text) {
  DbSettings s;
  apply_config_text(s, role, text, "test.conf");
  return s;
}

TEST(DbSettings, TrailingCommentsAfterASpaceOrTabAreNotPartOfTheValue) {
  const DbSettings s = parse(Role::Server,
                             "[database]   # where\n"
                             "host = db.example   # the host\n"
                             "port = 3307\t# tab before the hash\n"
                             "name = fleet\n"
                             "[server]\n"
                             "user = srv # account\n"
                             "alive_period_s = 2            # told to robots in Start\n");
  EXPECT_EQ(s.host, "db.example");
  EXPECT_EQ(s.port, 3307u);
  EXPECT_EQ(s.database, "fleet");
  EXPECT_EQ(s.user, "srv");
  ASSERT_EQ(s.program.count("alive_period_s"), 1u);
  EXPECT_EQ(s.program.at("alive_period_s"), "2");
}

TEST(DbSettings, AHashInsideAWordStaysInTheValue) {
  const DbSettings s = parse(Role::Operator, "[operator]\nuser = op\npassword = pa#ss#word\n");
  EXPECT_EQ(s.password, "pa#ss#word");
}

TEST(DbSettings, WholeLineCommentsAndOtherRolesSectionsAreSkipped) {
  const DbSettings s = parse(Role::Operator,
                             "# a comment\n; another\n[server]\nuser = srv\n[operator]\nuser = op   # me\n");
  EXPECT_EQ(s.user, "op");
  EXPECT_TRUE(s.program.empty());
}

TEST(DbSettings, AMalformedLineIsNamedByFileAndLine) {
  try {
    parse(Role::Operator, "[database]\nport = 3307 # ok\nport = x # not a port\n");
    FAIL() << "expected a refusal";
  } catch (const BadInput& e) {
    EXPECT_NE(std::string(e.what()).find("test.conf:3"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("got 'x'"), std::string::npos) << e.what();
  }
  EXPECT_THROW(parse(Role::Operator, "[database]\njust words # and a comment\n"), FileFormatError);
}

TEST(DbSettings, ProgramSettingsOfAnotherRoleNeedNotReadItsPasswordFile) {
  const std::string path =
      (std::filesystem::temp_directory_path() / ("db-settings-" + std::to_string(getpid()) + ".conf")).string();
  std::ofstream(path) << "[server]\nuser = s\npassword_file = /no/such/server.password\n"
                         "robot_radius_m = 0.4   # planning radius\n";
  const auto server = program_settings(Role::Server, path);
  ASSERT_EQ(server.size(), 1u);
  EXPECT_EQ(server.at("robot_radius_m"), "0.4");
  EXPECT_THROW(load_settings(Role::Server, path), IoError);  // the server itself must read it
  std::filesystem::remove(path);
}

TEST(DbSettings, HostsListTheNodesToFailOverBetweenInOrder) {
  const DbSettings s = parse(Role::Robot,
                             "[database]\n"
                             "port = 3310\n"
                             "hosts = db1:3306, db2 ,[::1]:3307,10.0.0.4   # the Galera nodes\n");
  ASSERT_EQ(s.hosts.size(), 4u);
  EXPECT_EQ(s.hosts[0], (DbEndpoint{"db1", 3306}));
  EXPECT_EQ(s.hosts[1], (DbEndpoint{"db2", 0}));
  EXPECT_EQ(s.hosts[2], (DbEndpoint{"::1", 3307}));
  EXPECT_EQ(s.hosts[3], (DbEndpoint{"10.0.0.4", 0}));
  // A host without a port gets the [database] port, wherever `port` stands in the file.
  const std::vector<DbEndpoint> e = endpoints(s);
  EXPECT_EQ(e[1], (DbEndpoint{"db2", 3310}));
  EXPECT_EQ(e[3], (DbEndpoint{"10.0.0.4", 3310}));
  EXPECT_EQ(e[0], (DbEndpoint{"db1", 3306}));
  // Without hosts: host and port alone.
  const DbSettings one = parse(Role::Robot, "[database]\nhost = h\nport = 3311\n");
  EXPECT_EQ(endpoints(one), (std::vector<DbEndpoint>{{"h", 3311}}));
}

TEST(DbSettings, MalformedHostsAreRefusedWithTheLineAndTheEntry) {
  for (const char* bad : {"hosts =", "hosts = db1,,db2", "hosts = db1:", "hosts = db1:0", "hosts = db1:70000",
                          "hosts = db1:x", "hosts = :3306", "hosts = [::1", "hosts = [::1]x", "hosts = a b:1"}) {
    try {
      parse(Role::Robot, std::string("[database]\n") + bad + "\n");
      ADD_FAILURE() << "accepted " << bad;
    } catch (const BadInput& e) {
      EXPECT_NE(std::string(e.what()).find("test.conf:2: hosts"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("expected hosts as 'host[:port]"), std::string::npos) << e.what();
    }
  }
  // Unknown keys of [database] are still refused, naming the ones it knows.
  try {
    parse(Role::Robot, "[database]\nhost_list = a\n");
    ADD_FAILURE() << "accepted host_list";
  } catch (const FileFormatError& e) {
    EXPECT_NE(std::string(e.what()).find("hosts"), std::string::npos) << e.what();
  }
}

TEST(DbSettings, FleetmapHostsOverridesTheFile) {
  DbSettings s = parse(Role::Robot, "[database]\nhosts = a:1, b:2\n");
  ::setenv("FLEETMAP_HOSTS", "c:3", 1);
  apply_environment(s);
  ::unsetenv("FLEETMAP_HOSTS");
  EXPECT_EQ(s.hosts, (std::vector<DbEndpoint>{{"c", 3}}));
  ::setenv("FLEETMAP_HOSTS", "c:3,", 1);
  EXPECT_THROW(apply_environment(s), BadInput);
  ::unsetenv("FLEETMAP_HOSTS");
}

}  // namespace
}  // namespace fleetmap
