// Several servers sharing the fleet by robot id (--partition I/N, server/core/robot_partition.h),
// against the real fleetmap-server processes and MariaDB, robots speaking plain SQL:
//   * with only the server of share 0/2 running, the robots with an even id are answered
//     and the others' requests stay in rr; the server of 1/2 then answers those;
//   * with both running, every request is answered exactly once, in order, and each
//     server's log names only requests of its own share's robots;
//   * a share that is no share (2/2, 1/0, "half") stops the server at start with exit 2
//     and a message naming the setting, from the flag and from FLEETMAP_SERVER_PARTITION.
#include <cstdlib>
#include <map>
#include <regex>
#include <set>

#include <gtest/gtest.h>

#include "tests/integration/server_fixture.h"
#include "tests/integration/test_db.h"

namespace fleetmap::test {
namespace {

using std::chrono::milliseconds;
using std::chrono::seconds;

constexpr const char* kMap = "part_map";

struct PartBot {
  std::string name;
  unsigned id = 0;
  std::unique_ptr<SqlRobot> robot;
  std::vector<unsigned long long> sent;               // GetPosEnd request ids, in order
  std::map<unsigned long long, int> answers_per_request;
  std::vector<unsigned long long> answered_in_order;  // request ids, in the order of the answers
};

// Request ids the server logged as handled (GetPosEnd without a goal: Error no_goal, at debug).
std::set<unsigned long long> handled(const std::string& log) {
  static const std::regex re(R"(request (\d+) \(GetPosEnd\): no_goal)");
  std::set<unsigned long long> out;
  for (auto it = std::sregex_iterator(log.begin(), log.end(), re); it != std::sregex_iterator(); ++it)
    out.insert(std::stoull((*it)[1]));
  return out;
}

void fresh_log(const std::string& name) { write_file(temp_path(name), ""); }

struct RemoveAtEnd {
  std::vector<std::string> names;
  ~RemoveAtEnd() {
    for (const std::string& n : names) run("fleetmap", "robot remove " + n);
  }
};

TEST(ServerPartition, EachShareIsAnsweredByItsServerOnlyAndExactlyOnce) {
  ensure_example_map(kMap);
  RemoveAtEnd cleanup;
  std::vector<PartBot> bots(6);
  for (size_t i = 0; i < bots.size(); ++i) {
    PartBot& b = bots[i];
    b.name = "part_r" + std::to_string(i);
    cleanup.names.push_back(b.name);
    const std::string pw = add_robot(b.name, kMap);
    b.id = static_cast<unsigned>(scalar("SELECT id FROM robots WHERE db_user = '" + b.name + "'"));
    b.robot = std::make_unique<SqlRobot>(b.name, pw);
  }
  size_t even = 0;
  for (const PartBot& b : bots) even += b.id % 2 == 0;
  ASSERT_GT(even, 0u);
  ASSERT_LT(even, bots.size());

  fresh_log("part_a.log");
  fresh_log("part_b.log");
  auto a = std::make_unique<ServerProcess>("--partition 0/2 --poll-max-ms 5", "part_a.log");
  std::map<std::string, unsigned long long> ready;
  for (PartBot& b : bots) ready[b.name] = b.robot->send("Ready", R"({"magic": 5})");
  for (PartBot& b : bots) {
    if (b.id % 2 != 0) continue;
    const std::vector<SqlAnswer> got = b.robot->receive(2, seconds(15));
    ASSERT_EQ(got.size(), 2u) << b.name << " (id " << b.id << ") not registered by the server of share 0/2\n" << a->log();
    EXPECT_EQ(got[0].op, "Start");
    EXPECT_EQ(got[0].request_id, ready[b.name]);
  }
  // The other share: a server polling every 5 ms at most had a second to answer them,
  // and must not have: their Ready is still waiting, untouched.
  std::this_thread::sleep_for(seconds(1));
  for (PartBot& b : bots) {
    if (b.id % 2 == 0) continue;
    EXPECT_TRUE(b.robot->peek().empty()) << b.name << " (id " << b.id << ") answered by the server of share 0/2";
    EXPECT_EQ(scalar("SELECT COUNT(*) FROM rr WHERE id = " + std::to_string(ready[b.name])), 1) << b.name;
  }

  auto b_server = std::make_unique<ServerProcess>("--partition 1/2 --poll-max-ms 5", "part_b.log");
  for (PartBot& b : bots) {
    if (b.id % 2 != 0) {
      const std::vector<SqlAnswer> got = b.robot->receive(2, seconds(15));
      ASSERT_EQ(got.size(), 2u) << b.name << " not registered by the server of share 1/2\n" << b_server->log();
      EXPECT_EQ(got[0].op, "Start");
      EXPECT_EQ(got[0].request_id, ready[b.name]);
    }
  }

  // Both running: 30 requests per robot, every one answered once, in order.
  constexpr int kRequests = 30;
  for (int i = 0; i < kRequests; ++i)
    for (PartBot& b : bots) b.sent.push_back(b.robot->send("GetPosEnd"));
  for (PartBot& b : bots) {
    const std::vector<SqlAnswer> got = b.robot->receive(kRequests, seconds(20));
    for (const SqlAnswer& ans : got) {
      ASSERT_TRUE(ans.request_id.has_value()) << b.name << ": " << ans.op;
      ++b.answers_per_request[*ans.request_id];
      b.answered_in_order.push_back(*ans.request_id);
      EXPECT_EQ(ans.op, "Error");
      EXPECT_EQ(ans.robot_id, b.id);
    }
    std::this_thread::sleep_for(milliseconds(100));
    EXPECT_TRUE(b.robot->peek().empty()) << b.name << ": answers beyond one per request";
    EXPECT_EQ(b.answered_in_order, b.sent) << b.name << ": not every request answered once, in order";
  }

  a.reset();  // SIGTERM: both logs complete
  b_server.reset();
  const std::set<unsigned long long> by_a = handled(read_file(temp_path("part_a.log")));
  const std::set<unsigned long long> by_b = handled(read_file(temp_path("part_b.log")));
  for (const PartBot& b : bots) {
    for (unsigned long long id : b.sent) {
      const bool mine_a = b.id % 2 == 0;
      EXPECT_EQ(by_a.count(id), mine_a ? 1u : 0u) << b.name << " (id " << b.id << ") request " << id;
      EXPECT_EQ(by_b.count(id), mine_a ? 0u : 1u) << b.name << " (id " << b.id << ") request " << id;
    }
  }
}

TEST(ServerPartition, ANoShareStopsTheServerAtStartWithExit2) {
  for (const char* bad : {"2/2", "1/0", "half", "1/2/3"}) {
    const RunResult r = run("fleetmap-server", std::string("--check --partition '") + bad + "'");
    EXPECT_EQ(r.exit_code, 2) << bad << ": " << r.err;
    EXPECT_NE(r.err.find("partition: expected I/N"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(std::string("'") + bad + "'"), std::string::npos) << r.err;
  }
  ::setenv("FLEETMAP_SERVER_PARTITION", "3/2", 1);
  const RunResult env = run("fleetmap-server", "--check");
  const RunResult env_bad_flag_good = run("fleetmap-server", "--check --partition 1/2");
  ::unsetenv("FLEETMAP_SERVER_PARTITION");
  EXPECT_EQ(env.exit_code, 2) << env.err;
  EXPECT_NE(env.err.find("FLEETMAP_SERVER_PARTITION"), std::string::npos) << env.err;
  // The environment is read before the flags, and a bad value there is refused even so:
  // a service must not start on a share nobody meant.
  EXPECT_EQ(env_bad_flag_good.exit_code, 2) << env_bad_flag_good.err;
  const RunResult good = run("fleetmap-server", "--check --partition 1/2");
  EXPECT_EQ(good.exit_code, 0) << good.err;
  EXPECT_NE(good.out.find("robots with id mod 2 = 1"), std::string::npos) << good.out;
}

}  // namespace
}  // namespace fleetmap::test
