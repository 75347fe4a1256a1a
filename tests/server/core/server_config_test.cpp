// ServerConfig::apply (server/core/server_config.h): defaults, settings from the file's
// [server] section, later settings (flags) over earlier ones, and bad values refused
// with the key and what was expected.
#include "server/core/server_config.h"

#include <fstream>
#include <regex>
#include <sstream>

#include <gtest/gtest.h>

#include "protocol/db_settings.h"

namespace fleetmap {
namespace {

std::string refusal(ServerConfig& c, const std::map<std::string, std::string>& s) {
  try {
    c.apply(s);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(ServerConfig, DefaultsAreTheDocumentedOnes) {
  // etc/fleetmap.conf.sample and fleetmap-server --help
  const ServerConfig c;
  EXPECT_EQ(c.alive_period_s, 1.0);
  EXPECT_EQ(c.lost_after_periods, 5);
  EXPECT_EQ(c.workers, 2);
  EXPECT_EQ(c.poll_max_ms, 10);
  EXPECT_EQ(c.batch_robots, 16u);
  EXPECT_EQ(c.batch_requests, 32u);
  EXPECT_EQ(c.max_full_map_segments, 20000u);
  EXPECT_EQ(c.ready_window_m, 100);
  EXPECT_EQ(c.max_window_m, 1000);
  EXPECT_EQ(c.max_image_bytes, 8u * 1024 * 1024);
  EXPECT_EQ(c.goal_tolerance_m, 0.5);
  EXPECT_EQ(c.robot_radius_m, 0.3);
  EXPECT_EQ(c.body_height_m, 1.0);
  EXPECT_EQ(c.topo_path_min_m, 60);
  EXPECT_EQ(c.object_ttl_s, 300);
  EXPECT_EQ(c.history_keep_s, 0);  // the history is kept unless a site says otherwise
  EXPECT_EQ(c.lock_wait_timeout_s, 1);
  EXPECT_EQ(c.commit_delay_ms, 0);
  EXPECT_EQ(c.robot_block_ms, 2000);
}

TEST(ServerConfig, TheSampleFilesSettingsUncommentedParseToTheDefaults) {
  // Each "# key = value   # why" of the sample's [server] section, uncommented as an
  // operator would, keeps its trailing comment: it must parse, and give the default.
  std::ifstream in(std::string(FLEETMAP_SOURCE_DIR) + "/etc/fleetmap.conf.sample");
  ASSERT_TRUE(in);
  std::ostringstream text;
  static const std::regex kSetting(R"(^# ([a-z_]+ = \S+\s+#.*)$)");
  std::string line;
  size_t uncommented = 0;
  std::string section;  // only [server]'s: other programs' sections have settings of their own
  while (std::getline(in, line)) {
    if (line.rfind("password_file", 0) == 0) continue;  // a file this machine may not have
    if (line.rfind("[", 0) == 0) section = line;
    std::smatch m;
    if (section == "[server]" && std::regex_match(line, m, kSetting)) {
      text << m[1] << "\n";
      ++uncommented;
    } else {
      text << line << "\n";
    }
  }
  EXPECT_GE(uncommented, 16u);
  DbSettings s;
  apply_config_text(s, Role::Server, text.str(), "fleetmap.conf.sample");
  EXPECT_EQ(s.program.size(), uncommented);
  ServerConfig c;
  c.apply(s.program);
  const ServerConfig d;
  EXPECT_EQ(c.alive_period_s, d.alive_period_s);
  EXPECT_EQ(c.lost_after_periods, d.lost_after_periods);
  EXPECT_EQ(c.workers, d.workers);
  EXPECT_EQ(c.poll_max_ms, d.poll_max_ms);
  EXPECT_EQ(c.max_image_bytes, d.max_image_bytes);
  EXPECT_EQ(c.goal_tolerance_m, d.goal_tolerance_m);
  EXPECT_EQ(c.robot_radius_m, d.robot_radius_m);
  EXPECT_EQ(c.object_ttl_s, d.object_ttl_s);
  EXPECT_EQ(c.commit_delay_ms, d.commit_delay_ms);
  EXPECT_EQ(c.robot_block_ms, d.robot_block_ms);
}

TEST(ServerConfig, EveryKeyOfTheFileIsApplied) {
  ServerConfig c;
  c.apply({{"alive_period_s", "0.5"},     {"lost_after_periods", "3"},   {"workers", "4"},
           {"poll_max_ms", "20"},         {"batch_robots", "8"},         {"batch_requests", "64"},
           {"max_full_map_segments", "500"}, {"ready_window_m", "50"},   {"max_window_m", "200"},
           {"max_image_bytes", "1024"},   {"goal_tolerance_m", "0.25"},  {"robot_radius_m", "0.4"},
           {"body_height_m", "1.5"},      {"object_ttl_s", "60"},        {"lock_wait_timeout_s", "2"},
           {"commit_delay_ms", "0"},      {"robot_block_ms", "500"},
           {"topo_path_min_m", "0"},      {"history_keep_s", "604800"}});
  EXPECT_EQ(c.alive_period_s, 0.5);
  EXPECT_EQ(c.lost_after_periods, 3);
  EXPECT_EQ(c.workers, 4);
  EXPECT_EQ(c.poll_max_ms, 20);
  EXPECT_EQ(c.batch_robots, 8u);
  EXPECT_EQ(c.batch_requests, 64u);
  EXPECT_EQ(c.max_full_map_segments, 500u);
  EXPECT_EQ(c.ready_window_m, 50);
  EXPECT_EQ(c.max_window_m, 200);
  EXPECT_EQ(c.max_image_bytes, 1024u);
  EXPECT_EQ(c.goal_tolerance_m, 0.25);
  EXPECT_EQ(c.robot_radius_m, 0.4);
  EXPECT_EQ(c.body_height_m, 1.5);
  EXPECT_EQ(c.object_ttl_s, 60);
  EXPECT_EQ(c.lock_wait_timeout_s, 2);
  EXPECT_EQ(c.commit_delay_ms, 0);
  EXPECT_EQ(c.robot_block_ms, 500);
  EXPECT_EQ(c.topo_path_min_m, 0);
  EXPECT_EQ(c.history_keep_s, 604800);
}

TEST(ServerConfig, FlagsAppliedAfterTheFileOverrideItAndLeaveTheRest) {
  // server_main: cfg.apply(file's [server]); cfg.apply(flags).
  ServerConfig c;
  c.apply({{"alive_period_s", "2"}, {"workers", "3"}});
  c.apply({{"workers", "1"}});
  EXPECT_EQ(c.workers, 1);
  EXPECT_EQ(c.alive_period_s, 2);
  EXPECT_EQ(c.batch_robots, 16u);
}

TEST(ServerConfig, AMalformedNumberIsRefusedNamingTheKeyAndWhatWasExpected) {
  for (const char* v : {"abc", "", "1.5x", "-1", "0", "nan", "inf"}) {
    ServerConfig c;
    const std::string m = refusal(c, {{"alive_period_s", v}});
    EXPECT_NE(m.find("[server] alive_period_s"), std::string::npos) << v << ": " << m;
    EXPECT_NE(m.find("expected a positive number"), std::string::npos) << v << ": " << m;
    EXPECT_NE(m.find("got '" + std::string(v) + "'"), std::string::npos) << v << ": " << m;
    EXPECT_EQ(c.alive_period_s, 1.0) << v;
  }
}

TEST(ServerConfig, ZeroIsAllowedOnlyWhereItMeansOff) {
  ServerConfig c;
  c.apply({{"commit_delay_ms", "0"}});
  EXPECT_EQ(c.commit_delay_ms, 0);
  const std::string m = refusal(c, {{"commit_delay_ms", "-5"}});
  EXPECT_NE(m.find("commit_delay_ms: expected a non-negative number, got '-5'"), std::string::npos) << m;
  EXPECT_NE(refusal(c, {{"workers", "0"}}).find("workers: expected a positive whole number up to 1024, got '0'"), std::string::npos);
}

TEST(ServerConfig, AHistoryKeptLongerThanACenturyIsRefused) {
  // Its cutoff in microseconds would overflow and fall in the future: every pose deleted.
  ServerConfig c;
  EXPECT_EQ(refusal(c, {{"history_keep_s", "1e300"}}),
            "[server] history_keep_s: expected seconds up to 100 years (3155760000), got '1e300'");
  EXPECT_EQ(c.history_keep_s, 0);
  c.apply({{"history_keep_s", "3155760000"}});
  EXPECT_EQ(c.history_keep_s, 3155760000.0);
}

TEST(ServerConfig, CountsMustBeWholeNumbers) {
  for (const char* key : {"batch_robots", "batch_requests", "max_full_map_segments", "max_image_bytes"}) {
    ServerConfig c;
    const std::string m = refusal(c, {{key, "1.5"}});
    EXPECT_EQ(m, "[server] " + std::string(key) + ": expected a positive whole number, got '1.5'") << key;
  }
  ServerConfig c;
  EXPECT_EQ(refusal(c, {{"workers", "2.5"}}), "[server] workers: expected a positive whole number up to 1024, got '2.5'");
  EXPECT_EQ(refusal(c, {{"workers", "5000"}}),
            "[server] workers: expected a positive whole number up to 1024, got '5000'");
  EXPECT_EQ(refusal(c, {{"lock_wait_timeout_s", "1e9"}}),
            "[server] lock_wait_timeout_s: expected a positive whole number up to 3600, got '1e9'");
  EXPECT_EQ(c.workers, 2);
}

TEST(ServerConfig, AnUnknownKeyIsRefusedByName) {
  ServerConfig c;
  EXPECT_EQ(refusal(c, {{"alive_period", "1"}}), "[server] unknown setting 'alive_period'");
}

}  // namespace
}  // namespace fleetmap
