// The robot client library against the real server: handshake, zoom-map refresh by
// distance and by time-out, pushed operations acknowledged, answers taken whatever the
// order of their ids, a database restart survived.
#include <functional>
#include <thread>

#include <gtest/gtest.h>

#include "client/robot_client.h"
#include "client/zoom_map_client.h"
#include "common/map/map_window.h"
#include "common/io/seed_format.h"
#include "tests/integration/server_fixture.h"
#include "tests/integration/test_db.h"

namespace fleetmap::test {
namespace {

class RobotClientTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ensure_example_map("client_map");
    const std::string pw = add_robot("client_r1", "client_map");
    settings_ = tcp_settings(Role::Inspector);
    settings_.user = "client_r1";
    settings_.password = pw;
    server_ = std::make_unique<ServerProcess>("", "client_server.log");
  }
  void TearDown() override {
    server_.reset();
    if (HasFailure()) std::cerr << read_file(temp_path("client_server.log")).substr(0, 20000);
  }
  // receive() until an answer satisfies pred or the timeout passes.
  std::optional<ReceivedAnswer> wait_for(RobotClient& c, const std::function<bool(const ReceivedAnswer&)>& pred,
                                         std::vector<ReceivedAnswer>* seen = nullptr) {
    for (int i = 0; i < 500; ++i) {
      for (ReceivedAnswer& a : c.receive()) {
        if (seen) seen->push_back(a);
        if (pred(a)) return a;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    return std::nullopt;
  }
  DbSettings settings_;
  std::unique_ptr<ServerProcess> server_;
};

TEST_F(RobotClientTest, HandshakeGivesRobotIdAndMap) {
  RobotClient client(settings_);
  const RobotSession s = client.ready(99);
  EXPECT_EQ(s.robot_id, static_cast<unsigned>(scalar("SELECT id FROM robots WHERE db_user = 'client_r1'")));
  EXPECT_EQ(s.map, read_seed_file(source_path("maps/example-campus.map")));
  EXPECT_EQ(client.robot_id(), s.robot_id);
  // Requests now carry the robot id, and the server accepts them.
  const auto id = client.send(RequestOp::GetPosEnd);
  auto a = client.await(id, 1);
  EXPECT_EQ(a[0].params["code"], "no_goal");
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM rr WHERE db_user = 'client_r1'"), 0);
}

TEST_F(RobotClientTest, ZoomMapRefreshesByDistanceAndByTimeout) {
  RobotClient client(settings_);
  client.ready(1);
  ZoomMapClient zoom(client, ZoomMapOptions{20, 5, 100});
  const Map whole = read_seed_file(source_path("maps/example-campus.map"));
  auto settle = [&](double now) {
    auto got = wait_for(client, [&](const ReceivedAnswer& a) { return zoom.on_answer(a, now) || !zoom.pending(); });
    return got.has_value();
  };
  EXPECT_EQ(zoom.update({20, 30}, 0), ZoomMap::Reason::NoWindow);
  ASSERT_TRUE(settle(0));
  ASSERT_TRUE(zoom.window());
  EXPECT_EQ(*zoom.window(), clip_map(whole, window_rect(whole.border, {20, 30}, 20, 20)));
  EXPECT_EQ(zoom.update({23, 30}, 10), ZoomMap::Reason::None);  // 3 m < 5 m, 10 s < 100 s
  EXPECT_EQ(zoom.update({26, 30}, 20), ZoomMap::Reason::Distance);
  ASSERT_TRUE(settle(20));
  EXPECT_EQ(*zoom.window(), clip_map(whole, window_rect(whole.border, {26, 30}, 20, 20)));
  EXPECT_EQ(zoom.update({26, 31}, 119), ZoomMap::Reason::None);
  EXPECT_EQ(zoom.update({26, 31}, 121), ZoomMap::Reason::Timeout);
  ASSERT_TRUE(settle(121));
  EXPECT_EQ(zoom.window()->border.rect(), (Rect{16, 21, 36, 40}));
}

TEST_F(RobotClientTest, PushedGoalAndAbortAreAcknowledged) {
  RobotClient client(settings_);
  client.ready(5);
  ASSERT_EQ(run("fleetmap", "goal client_r1 12 8").exit_code, 0);
  auto goal = wait_for(client, [](const ReceivedAnswer& a) { return a.op == "SetPosEnd"; });
  ASSERT_TRUE(goal);
  EXPECT_EQ(goal->params["x"], 12.0);
  const std::string task = "(SELECT MAX(t.id) FROM tasks t JOIN robots r ON r.id = t.robot_id WHERE r.db_user = 'client_r1')";
  for (int i = 0; i < 300 && scalar("SELECT state = 'acknowledged' FROM tasks WHERE id = " + task) == 0; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  EXPECT_EQ(scalar("SELECT state = 'acknowledged' FROM tasks WHERE id = " + task), 1);
  ASSERT_EQ(run("fleetmap", "abort client_r1 --reason stop").exit_code, 0);
  auto abort = wait_for(client, [](const ReceivedAnswer& a) { return a.op == "Abort"; });
  ASSERT_TRUE(abort);
  for (int i = 0; i < 300 && scalar("SELECT state = 'aborted' FROM tasks WHERE id = " + task) == 0; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  EXPECT_EQ(scalar("SELECT state = 'aborted' FROM tasks WHERE id = " + task), 1);
}

TEST_F(RobotClientTest, AliveTimerKeepsTheRobotFromBeingLost) {
  server_.reset();
  server_ = std::make_unique<ServerProcess>("--alive-period 0.2 --lost-after 3", "client_server.log");
  RobotClient client(settings_);
  const RobotSession s = client.ready(3);
  client.start_alive(std::chrono::milliseconds(static_cast<int>(s.alive_period_s * 1000)));
  std::this_thread::sleep_for(std::chrono::milliseconds(1500));
  EXPECT_EQ(scalar("SELECT state = 'ready' FROM robots WHERE db_user = 'client_r1'"), 1);
  client.stop_alive();
  std::this_thread::sleep_for(std::chrono::milliseconds(1500));
  EXPECT_EQ(scalar("SELECT state = 'lost' FROM robots WHERE db_user = 'client_r1'"), 1);
}

// On a Galera cluster, servers on two nodes number their answers from each node's own
// counter: an answer with a lower id can commit after one with a higher id was read
// (RobotClient::fetch). Here the two answers are written by hand, the higher id first.
TEST_F(RobotClientTest, TakesAnAnswerThatCommitsAfterOneWithAHigherId) {
  RobotClient client(settings_);
  const RobotSession s = client.ready(1);
  server_.reset();  // nobody else answers
  const long long top = scalar("SELECT MAX(id) FROM sa") + 100;
  auto answer = [&](long long id, const std::string& code) {
    auto c = admin();
    mysqlpp::Query q = c->query();
    q << "INSERT INTO sa (id, robot_id, db_user, op, params) VALUES (" << id << ", " << s.robot_id
      << ", 'client_r1', 'Error', " << mysqlpp::quote << Json{{"code", code}}.dump() << ")";
    q.execute();
  };
  auto has_code = [](const std::string& code) {
    return [code](const ReceivedAnswer& a) { return a.params.value("code", "") == code; };
  };
  answer(top, "higher");
  ASSERT_TRUE(wait_for(client, has_code("higher")));
  answer(top - 50, "lower");
  EXPECT_TRUE(wait_for(client, has_code("lower"))) << "the later answer with the lower id was never taken";
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM sa WHERE db_user = 'client_r1' AND sentinel = 0"), 0);
}

// A robot's statement waits on a row lock for seconds, not InnoDB's 50 s: on a Galera
// cluster a replicated write waiting behind it would stall every node. Here an admin
// holds the robot's answer row while the robot deletes it: the delete gives up and is
// sent again until the client's reconnect_for (3 s) runs out, and once the lock is gone
// it goes through, the answer handed over once.
TEST_F(RobotClientTest, ALockHeldElsewhereHoldsTheRobotForSecondsOnly) {
  RobotClient client(settings_, std::chrono::seconds(3));
  const RobotSession s = client.ready(1);
  server_.reset();  // nobody else answers
  {
    auto c = admin();
    mysqlpp::Query q = c->query();
    q << "INSERT INTO sa (robot_id, db_user, op, params) VALUES (" << s.robot_id << ", 'client_r1', 'Error', "
      << mysqlpp::quote << Json{{"code", "held"}}.dump() << ")";
    q.execute();
  }
  auto holder = admin();
  holder->query("START TRANSACTION").execute();
  holder->query("SELECT id FROM sa WHERE db_user = 'client_r1' FOR UPDATE").store();

  size_t handed = 0;
  auto take = [&] {
    for (const ReceivedAnswer& a : client.receive()) handed += a.params.value("code", "") == "held";
  };
  const auto t0 = std::chrono::steady_clock::now();
  unsigned errnum = 0;
  try {
    for (int i = 0; i < 2000; ++i) {
      take();
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
  } catch (const mysqlpp::BadQuery& e) {
    errnum = e.errnum();
  }
  const double waited_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_EQ(errnum, 1205u) << "the delete should give up on the held lock";
  EXPECT_LT(waited_s, 20.0) << "one robot statement waited on a lock like InnoDB's default (50 s)";

  holder->query("ROLLBACK").execute();
  for (int i = 0; i < 200 && scalar("SELECT COUNT(*) FROM sa WHERE db_user = 'client_r1' AND sentinel = 0") > 0; ++i) {
    take();
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM sa WHERE db_user = 'client_r1' AND sentinel = 0"), 0);
  EXPECT_EQ(handed, 1u) << "the answer whose delete was retried was handed over again";
}

// The client polls sa_mine on its WaitPolicy's schedule (protocol/wait_policy.h), not on
// every call: idle, a control loop calling receive() every millisecond costs one poll per
// idle_ms; with an answer due and no server to answer it, one poll per gap.
TEST_F(RobotClientTest, PollsOnTheWaitPolicysSchedule) {
  WaitPolicy w;
  w.first_poll_ms = 1;
  w.min_ms = w.max_ms = 20;
  w.backoff = 0;
  w.idle_ms = 300;
  RobotClient client(settings_, std::chrono::seconds(60), w);
  client.ready(4);
  using std::chrono::milliseconds;
  auto count_polls = [&](milliseconds span, const std::function<void()>& step) {
    const size_t before = client.polls();
    const auto until = std::chrono::steady_clock::now() + span;
    while (std::chrono::steady_clock::now() < until) step();
    return client.polls() - before;
  };
  const size_t idle = count_polls(milliseconds(1000), [&] {
    client.receive();
    std::this_thread::sleep_for(milliseconds(1));
  });
  EXPECT_GE(idle, 3u);  // 1000 ms / 300 ms
  EXPECT_LE(idle, 4u);
  server_.reset();  // nobody answers: the SendGPS stays due
  const auto id = client.send(RequestOp::SendGPS, Json{{"lat", 10.5}, {"lon", 20.25}});
  const size_t due = count_polls(milliseconds(400), [&] {
    client.receive();
    std::this_thread::sleep_for(milliseconds(1));
  });
  EXPECT_GE(due, 15u);  // 400 ms / 20 ms, the first 1 ms after the send
  EXPECT_LE(due, 22u);
  const size_t awaiting = client.polls();
  EXPECT_THROW(client.await(id, 1, milliseconds(300)), RobotClientError);
  EXPECT_GE(client.polls() - awaiting, 12u);
  EXPECT_LE(client.polls() - awaiting, 17u);
}

TEST_F(RobotClientTest, SurvivesADatabaseRestart) {
  RobotClient client(settings_);
  client.ready(8);
  const std::string db = db_script();
  ASSERT_EQ(std::system((db + " stop >/dev/null").c_str()), 0);
  std::thread restart([&] {
    std::this_thread::sleep_for(std::chrono::seconds(1));
    std::system((db + " start >/dev/null").c_str());
  });
  // Sent while the database is down: the client retries until it is back.
  const auto id = client.send(RequestOp::SendGPS, Json{{"lat", 10.5}, {"lon", 20.25}});
  restart.join();
  auto a = client.await(id, 1, std::chrono::seconds(30));
  EXPECT_EQ(a[0].op, "OpAck");
  EXPECT_GE(client.reconnects(), 1u);
}

}  // namespace
}  // namespace fleetmap::test
