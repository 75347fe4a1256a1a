// A robot that blocks another robot is ended after [server] robot_block_ms (SPEC 5.3: no
// robot can stall another). Sentinels keep robots out of each other's answers
// (sa_lock_test.cpp); what two robots still share is rr and its AUTO_INCREMENT. Robot A
// runs an INSERT INTO rr ... SELECT over its own answers that sleeps on the second row:
// the statement holds rr's AUTO-INC table lock (innodb_autoinc_lock_mode 1) while it
// sleeps, so robot B's plain request waits on A. The real server, started with
// --robot-block-ms 600, must end A's connection after about that long (not at once, not
// after A's 20 s), log both names, and B's request must then be answered.
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "tests/integration/server_fixture.h"
#include "tests/integration/test_db.h"

namespace fleetmap::test {
namespace {

using Clock = std::chrono::steady_clock;
using std::chrono::milliseconds;
using std::chrono::seconds;

constexpr const char* kMap = "robot_block_map";

void push_answer(mysqlpp::Connection& db, const std::string& name) {
  mysqlpp::Query q = db.query();
  q << "INSERT INTO sa (robot_id, db_user, request_id, op, params) SELECT id, db_user, NULL, 'OpAck', "
       "'{\"request_id\": 0}' FROM robots WHERE db_user = "
    << mysqlpp::quote << name;
  q.execute();
}

TEST(RobotBlock, RobotBlockingAnotherRobotIsEndedAfterTheBound) {
  ensure_example_map(kMap);
  const std::string tag = "rb" + std::to_string(getpid());
  const std::string a_name = tag + "_a", b_name = tag + "_b";
  const RemoveRobotsAtEnd cleanup{{a_name, b_name}};
  const std::string a_pw = add_robot(a_name, kMap), b_pw = add_robot(b_name, kMap);
  {
    auto db = admin();
    push_answer(*db, a_name);
    push_answer(*db, a_name);
  }
  const std::string log_name = "robot_block.log";
  write_file(temp_path(log_name), "");
  auto server = std::make_unique<ServerProcess>("--workers 2 --robot-block-ms 600", log_name);

  // B registers first (a request before Ready is refused).
  SqlRobot b(b_name, b_pw);
  b.send("Ready", R"({"magic": 2})");
  ASSERT_EQ(b.receive(2, seconds(10)).size(), 2u) << "B got no Start + SetMap";

  // A: one row inserted at once (the AUTO-INC lock taken), then 20 s of sleep on the second.
  SqlRobot a(a_name, a_pw);
  std::atomic<bool> a_ended{false};
  std::atomic<double> a_took_s{0};
  std::thread holder([&] {
    const auto t0 = Clock::now();
    try {
      a.connection()
          .query("INSERT INTO rr (op, params) SELECT 'SendGPS', '{\"lat\": 1, \"lon\": 2}' FROM sa_mine "
                 "WHERE SLEEP(IF(id = (SELECT MAX(id) FROM sa_mine), 20, 0)) = 0 ORDER BY id")
          .execute();
    } catch (const mysqlpp::Exception&) {
      a_ended = true;
    }
    a_took_s = std::chrono::duration<double>(Clock::now() - t0).count();
  });
  std::this_thread::sleep_for(milliseconds(300));

  const auto t0 = Clock::now();
  const auto gps = b.send("SendGPS", R"({"lat": 41.4, "lon": 2.1})");
  const double b_wait_s = std::chrono::duration<double>(Clock::now() - t0).count();
  holder.join();
  std::cout << "[ info ] B's INSERT INTO rr waited " << b_wait_s << " s; A's statement ran " << a_took_s << " s\n";
  // B really waited on A (the case is real), about the bound, and far less than A's sleep.
  EXPECT_GT(b_wait_s, 0.25) << "B did not wait on A: the test proves nothing";
  EXPECT_LT(b_wait_s, 5.0) << "A was not ended within the bound";
  EXPECT_TRUE(a_ended) << "A's statement completed";
  EXPECT_LT(a_took_s, 6.0);
  const std::vector<SqlAnswer> got = b.receive(1, seconds(5));
  ASSERT_EQ(got.size(), 1u);
  EXPECT_EQ(got[0].request_id, gps);
  EXPECT_EQ(got[0].op, "OpAck");

  // A's statement was rolled back with its connection: none of its requests are in rr, or
  // answered; its two answers wait for it.
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM rr WHERE db_user = '" + a_name + "'"), 0);
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM sa WHERE sentinel = 0 AND db_user = '" + a_name + "'"), 2);
  const std::string log = read_file_once_it_has(temp_path(log_name), "of robot " + a_name + ": its transaction");
  EXPECT_NE(log.find("of robot " + a_name + ": its transaction"), std::string::npos) << log.substr(0, 6000);
  EXPECT_NE(log.find("blocked robot " + b_name + " for "), std::string::npos) << log.substr(0, 6000);
  EXPECT_EQ(log.find("of robot " + b_name + ":"), std::string::npos) << "B was ended too:\n" << log.substr(0, 6000);
}

}  // namespace
}  // namespace fleetmap::test
