// README "Exit codes", checked on the built programs, with no database: each code is
// provoked by the input that means it.
#include <gtest/gtest.h>

#include "tests/server/cli/cli_run.h"

namespace fleetmap::test {
namespace {

// example-room.map with its line `line` (1-based) replaced by `text`.
std::string room_with_line(size_t line, const std::string& text) {
  std::istringstream in(slurp(repo_path("maps/example-room.map")));
  std::string out, l;
  for (size_t no = 1; std::getline(in, l); ++no) out += (no == line ? text : l) + "\n";
  return out;
}

std::string first_line(const std::string& s) { return s.substr(0, s.find('\n')); }

TEST(FleetmapExitCodes, UnknownOptionIs64WithCli11sMessage) {
  EXPECT_EQ(run_cli("fleetmap", "--bogus").exit_code, 64);  // "A subcommand is required"
  const CliResult r = run_cli("fleetmap", "map check " + repo_path("maps/example-room.map") + " --bogus");
  EXPECT_EQ(r.exit_code, 64);
  EXPECT_NE(r.err.find("not expected: --bogus"), std::string::npos) << r.err;
  EXPECT_EQ(r.out, "");  // the command did not run
}

TEST(FleetmapExitCodes, NoSubcommandIs64) { EXPECT_EQ(run_cli("fleetmap", "").exit_code, 64); }

TEST(FleetmapExitCodes, HelpIs0) {
  const CliResult r = run_cli("fleetmap", "--help");
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.out.find("Exit codes:"), std::string::npos);
}

TEST(FleetmapExitCodes, MalformedMapFileIs2WithFileAndLine) {
  // Line 6 is the first obstacle's header "1;1;4;wall,concrete;": NS must be a number.
  ASSERT_EQ(first_line(room_with_line(6, "X")), "border;");
  const std::string bad = scratch_file("bad-ns.map");
  spit(bad, room_with_line(6, "1;1;four;wall,concrete;"));
  const CliResult r = run_cli("fleetmap", "map check " + bad);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err.rfind(bad + ":6: ", 0), 0u) << r.err;  // as is, for editors
  EXPECT_EQ(r.out, "");
}

// A file that cannot be opened is an I/O failure (1), as for every other file a command
// reads: 4 means a named thing of the database (map, robot, graph) is missing, which a
// script must be able to tell from a wrong path.
TEST(FleetmapExitCodes, MissingMapFileIs1) {
  const std::string missing = scratch_file("no-such.map");
  const CliResult r = run_cli("fleetmap", "map check " + missing);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find(missing), std::string::npos) << r.err;
  EXPECT_EQ(run_cli("fleetmap", "plan --file " + missing + " 1 1 3 3").exit_code, 1);
  EXPECT_EQ(run_cli("fleetmap", "scan --file " + missing + " 1 1 0").exit_code, 1);
}

TEST(FleetmapExitCodes, BadParameterValueIs2) {
  const std::string room = repo_path("maps/example-room.map");
  EXPECT_EQ(run_cli("fleetmap", "plan --file " + room + " 1 1 abc 3").exit_code, 2);
  EXPECT_EQ(run_cli("fleetmap", "scan --file " + room + " 1 nan 0").exit_code, 2);
  // The map name is checked before any connection is tried.
  const CliResult r = run_cli("fleetmap", "map import " + room + " --name 'no spaces'");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("expected a map name"), std::string::npos) << r.err;
}

TEST(FleetmapExitCodes, WrongPositionalCountIs64) {
  const std::string room = repo_path("maps/example-room.map");
  EXPECT_EQ(run_cli("fleetmap", "plan --file " + room + " 1 1 3").exit_code, 64);
  EXPECT_EQ(run_cli("fleetmap", "map check").exit_code, 64);
}

TEST(FleetmapExitCodes, NoPathIs3) {
  // A goal outside the border (-0.5..15.5 both ways): no robot reaches it.
  const std::string room = repo_path("maps/example-room.map");
  const CliResult r = run_cli("fleetmap", "plan --file " + room + " 2 2 40 40");
  EXPECT_EQ(r.exit_code, 3);
  EXPECT_NE(r.err.find("goal (40.000, 40.000) is blocked"), std::string::npos) << r.err;
}

TEST(FleetmapExitCodes, UnreachableDatabaseIs1WithOneReadableLine) {
  // Port 1 on loopback: nothing listens, the connection is refused at once.
  const CliResult r = run_cli("fleetmap", "--host 127.0.0.1 --port 1 --user nobody map list");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err.rfind("fleetmap: ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find("cannot connect"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;
}

TEST(ServerExitCodes, UsageBadSettingAndUnreadableConfig) {
  EXPECT_EQ(run_cli("fleetmap-server", "--bogus").exit_code, 64);
  const CliResult bad = run_cli("fleetmap-server", "--workers abc");
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("workers"), std::string::npos) << bad.err;
  const std::string conf = scratch_file("bad.conf");
  spit(conf, "[server]\nworkers 3\n");
  const CliResult malformed = run_cli("fleetmap-server", "--config " + conf);
  EXPECT_EQ(malformed.exit_code, 2);
  EXPECT_EQ(malformed.err.rfind(conf + ":2: expected 'key = value'", 0), 0u) << malformed.err;
  const CliResult missing = run_cli("fleetmap-server", "--config " + scratch_file("no-such.conf"));
  EXPECT_EQ(missing.exit_code, 1);
  EXPECT_NE(missing.err.find("cannot read config file"), std::string::npos) << missing.err;
}

TEST(RobotExitCodes, UsageBadMapFileAndMissingMapFile) {
  EXPECT_EQ(run_cli("fleetmap-robot", "--bogus").exit_code, 64);
  const CliResult no_start = run_cli("fleetmap-robot", "");
  EXPECT_EQ(no_start.exit_code, 64);
  EXPECT_NE(no_start.err.find("--start X Y THETA is required"), std::string::npos) << no_start.err;
  EXPECT_EQ(run_cli("fleetmap-robot", "--trials 1 --presets nope").exit_code, 64);

  const std::string bad = scratch_file("robot-bad.map");
  spit(bad, room_with_line(6, "1;1;four;wall,concrete;"));
  const CliResult r = run_cli("fleetmap-robot", "--trials 1 --skip-tracking --map-file " + bad);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find(bad + ":6: "), std::string::npos) << r.err;
  EXPECT_EQ(run_cli("fleetmap-robot", "--trials 1 --skip-tracking --map-file " + scratch_file("none.map")).exit_code,
            1);
}

}  // namespace
}  // namespace fleetmap::test
