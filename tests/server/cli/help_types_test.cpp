// --help shows each numeric option with its type (FLOAT, UINT, INT) or its unit
// (SECONDS, METRES, ...), never TEXT: the options expected numeric are listed here, by
// hand, not taken from the programs.
#include <map>
#include <regex>
#include <vector>

#include <gtest/gtest.h>

#include "tests/server/cli/cli_run.h"

namespace fleetmap::test {
namespace {

// The type word --help prints after `option` ("--radius FLOAT:..." -> "FLOAT"), or "" when
// the option is not listed.
std::string shown_type(const std::string& help, const std::string& option) {
  const std::regex line("(^|\\n)\\s+(-\\w,)?" + option +
                        "(,[-\\w]+)? ([^ \\n:=]+)");
  std::smatch m;
  if (!std::regex_search(help, m, line)) return "";
  return m[4];
}

struct Case {
  std::string program, command;
  std::vector<std::string> numeric;
};

const std::vector<Case> kCases = {
    {"fleetmap", "", {"--port"}},
    {"fleetmap", "map check", {"--height", "--in-out", "--margin"}},
    {"fleetmap", "map import", {"--height", "--in-out", "--margin"}},
    {"fleetmap", "map georef", {"LAT", "LON", "--heading", "--control", "--offset", "--rotation"}},
    {"fleetmap", "window", {"X", "Y", "W", "H"}},
    {"fleetmap", "map slice", {"--height", "--resolution"}},
    {"fleetmap", "map nav2", {"--laser-height", "--resolution"}},
    {"fleetmap", "plan", {"ARGS", "--radius", "--seed", "--body-height", "--attempts", "--max-time"}},
    {"fleetmap", "scan", {"ARGS", "--height", "--beams", "--fov", "--rmax"}},
    {"fleetmap", "robot add", {"--max-connections", "--laser-height", "--radius", "--height"}},
    {"fleetmap", "robot set", {"--laser-height", "--radius", "--height"}},
    {"fleetmap", "goal", {"XY", "--margin"}},
    {"fleetmap", "pose-ini", {"POSE"}},
    {"fleetmap", "tasks", {"--limit"}},
    {"fleetmap", "topo route", {"--radius"}},
    {"fleetmap", "objects list", {"--within"}},
    {"fleetmap", "objects near", {"X", "Y", "-k"}},
    {"fleetmap", "avoid at", {"X", "Y"}},
    {"fleetmap-server",
     "",
     {"--alive-period", "--lost-after", "--workers", "--poll-max-ms", "--batch-robots", "--batch-requests",
      "--max-full-map-segments", "--ready-window", "--max-window", "--max-image-bytes", "--goal-tolerance",
      "--robot-radius", "--object-ttl", "--history-keep", "--commit-delay-ms", "--port"}},
    {"fleetmap-robot",
     "",
     {"--port", "--start", "--duration", "--laser-height", "--beams", "--laser-sigma", "--people", "--particles",
      "--tracking-particles", "--speed", "--zoom-window", "--seed", "--localize-updates", "--magic", "--trials",
      "--look-around"}},
};

TEST(HelpTypes, TheParserFindsTypes) {
  const std::string help = "Options:\n  --radius FLOAT:FLOAT in [0 - 100]=0.3\n  -o,--output TEXT  out\n  X FLOAT REQUIRED\n";
  EXPECT_EQ(shown_type(help, "--radius"), "FLOAT");
  EXPECT_EQ(shown_type(help, "--output"), "TEXT");
  EXPECT_EQ(shown_type(help, "X"), "FLOAT");
  EXPECT_EQ(shown_type(help, "--missing"), "");
}

TEST(HelpTypes, NoNumericOptionIsShownAsText) {
  for (const Case& c : kCases) {
    const CliResult r = run_cli(c.program, c.command + " --help");
    ASSERT_EQ(r.exit_code, 0) << c.program << " " << c.command << ": " << r.err;
    for (const std::string& option : c.numeric) {
      const std::string type = shown_type(r.out, option);
      SCOPED_TRACE(c.program + " " + c.command + " " + option);
      EXPECT_NE(type, "") << "not listed in:\n" << r.out;
      EXPECT_NE(type, "TEXT") << r.out;
    }
  }
}

}  // namespace
}  // namespace fleetmap::test
