// dispatch() and serve_requests() (server/daemon/dispatch.h): the checks every op
// shares, an Error that leaves the robot as it was, and a batch in which one robot's bad
// request costs nobody else anything.
#include "server/daemon/dispatch.h"

#include <gtest/gtest.h>

#include "tests/server/daemon/fake_stores.h"

namespace fleetmap::fakes {
namespace {

TEST(Dispatch, UnknownOpsAreRefusedByName) {
  Bench b;
  for (const char* op : {"ready", "SENDPOS", "Ready ", "", "DropTable"}) {
    const RequestWrites w = b.send(op, "{}");
    EXPECT_EQ(error_code(w), "unknown_op") << op;
    EXPECT_EQ(w.answers.at(0).request_id, b.next_id);
    EXPECT_EQ(w.answers.at(0).params["request_id"], b.next_id);
  }
}

TEST(Dispatch, ARobotIdThatIsNotTheAccountsIsNotYourRobot) {
  Bench b;
  Request r = request(5, "r7", "Alive", "{}");
  r.robot_id = 8;
  const RequestWrites w = dispatch(b.config, b.records, b.maps, b.served, r);
  ASSERT_EQ(error_code(w), "not_your_robot");
  EXPECT_EQ(w.answers[0].robot_id, 7u);  // answered to the account's robot
  EXPECT_EQ(w.answers[0].db_user, "r7");
  r.robot_id = 7;
  EXPECT_TRUE(dispatch(b.config, b.records, b.maps, b.served, r).answers.empty());
}

TEST(Dispatch, AnErrorLeavesTheRobotAndItsTaskAsTheyWere) {
  Bench b;
  b.robot().x = 1;
  b.served.open_task = task(3, 7, TaskState::Acknowledged, 5, 5);
  const ServedRobot before = b.served;
  EXPECT_EQ(error_code(b.send("GetMap", R"({"x": 99, "y": 99, "w": 1, "h": 1})")), "bad_params");
  EXPECT_EQ(b.served.robot.x, before.robot.x);
  EXPECT_EQ(b.served.robot.state, before.robot.state);
  EXPECT_EQ(b.served.open_task->state, TaskState::Acknowledged);
}

// A sink that keeps what the batch wrote, in order.
struct VectorSink : BatchSink {
  std::vector<std::pair<unsigned long long, RequestWrites>> served_requests;
  std::vector<std::pair<RobotRow, std::string>> rows;
  void served(const Request& r, RequestWrites&& w) override { served_requests.emplace_back(r.id, std::move(w)); }
  void robot_seen(const RobotRow& r, const std::string& at) override { rows.emplace_back(r, at); }
};

struct BatchTest : ::testing::Test {
  ServerConfig config;
  FakeRecords records;
  FakeMaps maps;
  std::map<std::string, ServedRobot> robots;
  VectorSink sink;
  void SetUp() override {
    maps.add(1, "room", walled_room());
    robots.emplace("r7", registered_robot(7, "r7"));
    robots.emplace("r8", registered_robot(8, "r8"));
  }
  void serve(const std::vector<Request>& reqs) {
    serve_requests(
        robots, reqs,
        [&](ServedRobot& s, const Request& r) { return dispatch(config, records, maps, s, r); }, sink);
  }
};

TEST_F(BatchTest, OneRobotsMalformedRequestIsAnErrorAndTheOthersAreAnswered) {
  serve({request(1, "r7", "SendPos", R"({"x": 1, "y": 1, "theta": 0, "v": 1})"),
         request(2, "r8", "GetPosEnd", R"({"x": )"),  // not JSON
         request(3, "r7", "Stopped", "{}"), request(4, "r8", "SendGPS", R"({"lat": 1, "lon": 2})"),
         request(5, "r8", "SetObject", R"({"x": 1})")});
  ASSERT_EQ(sink.served_requests.size(), 5u);
  for (size_t i = 0; i < 5; ++i) EXPECT_EQ(sink.served_requests[i].first, i + 1);  // in id order
  EXPECT_EQ(sink.served_requests[0].second.poses.size(), 1u);
  EXPECT_EQ(error_code(sink.served_requests[1].second), "bad_json");
  EXPECT_EQ(sink.served_requests[1].second.answers[0].db_user, "r8");
  EXPECT_EQ(sink.served_requests[2].second.answers.at(0).op, AnswerOp::OpAck);
  EXPECT_EQ(sink.served_requests[3].second.answers.at(0).op, AnswerOp::OpAck);
  EXPECT_EQ(sink.served_requests[3].second.fixes.size(), 1u);
  EXPECT_EQ(error_code(sink.served_requests[4].second), "bad_params");
  EXPECT_TRUE(records.objects.empty());
  // Both robots' rows, each last seen at its last request.
  ASSERT_EQ(sink.rows.size(), 2u);
  EXPECT_EQ(sink.rows[0].first.db_user, "r7");
  EXPECT_EQ(sink.rows[0].first.state, RobotState::Stopped);
  EXPECT_EQ(sink.rows[0].first.x, 1);
  EXPECT_EQ(sink.rows[0].second, "2026-11-28 07:00:03.000000");
  EXPECT_EQ(sink.rows[1].second, "2026-11-28 07:00:05.000000");
}

TEST_F(BatchTest, ALostRobotThatSendsAnythingIsReadyAgain) {
  robots.at("r7").robot.state = RobotState::Lost;
  robots.at("r8").robot.state = RobotState::Lost;
  serve({request(1, "r7", "Alive", "[]")});  // even a malformed request
  ASSERT_EQ(sink.rows.size(), 1u);  // r8 sent nothing: not written, still lost
  EXPECT_EQ(sink.rows[0].first.state, RobotState::Ready);
  EXPECT_EQ(robots.at("r8").robot.state, RobotState::Lost);
}

TEST_F(BatchTest, ARobotWhoseLocalizationIsLostIsLocalizingUntilItSendsAPose) {
  robots.at("r7").robot.x = 4;
  robots.at("r7").open_task = task(3, 7, TaskState::Active, 3, 8);
  serve({request(1, "r7", "SendPos", R"({"status": "lost"})"), request(2, "r7", "Alive", "{}")});
  ASSERT_EQ(sink.rows.size(), 1u);
  // Another request (Alive) does not bring it back, unlike a silent robot.
  EXPECT_EQ(sink.rows[0].first.state, RobotState::Localizing);
  EXPECT_EQ(sink.rows[0].first.x, 4);  // the last known pose stays
  EXPECT_TRUE(sink.served_requests[0].second.poses.empty());  // no trajectory point
  // Its task failed, with the reason.
  EXPECT_FALSE(robots.at("r7").open_task);
  ASSERT_EQ(records.task_states.size(), 1u);
  EXPECT_EQ(records.task_states[0], (std::pair<unsigned long long, TaskState>{3, TaskState::Failed}));
  EXPECT_NE(records.task_reasons[3].find("localization"), std::string::npos) << records.task_reasons[3];
  sink.rows.clear();
  serve({request(3, "r7", "SendPos", R"({"x": 6, "y": 2, "theta": 0, "v": 0})")});
  ASSERT_EQ(sink.rows.size(), 1u);
  EXPECT_EQ(sink.rows[0].first.state, RobotState::Ready);
  EXPECT_EQ(sink.rows[0].first.x, 6);
}

TEST_F(BatchTest, ARemovedRobotsRequestsLeaveTheQueueUnanswered) {
  robots.at("r8").robot.removed = true;
  serve({request(1, "r8", "Ready", R"({"magic": 1})"), request(2, "r7", "Alive", "{}")});
  ASSERT_EQ(sink.served_requests.size(), 2u);
  EXPECT_TRUE(sink.served_requests[0].second.answers.empty());
  EXPECT_TRUE(records.sessions.empty());
  ASSERT_EQ(sink.rows.size(), 1u);
  EXPECT_EQ(sink.rows[0].first.db_user, "r7");
}

TEST_F(BatchTest, ABatchsRequestsTakeEffectInOrder) {
  // SendPos then GetPath in one batch: the path starts at the pose just sent.
  robots.at("r7").open_task = task(3, 7, TaskState::Assigned, 3, 8);
  serve({request(1, "r7", "SendPos", R"({"x": 2, "y": 2, "theta": 0, "v": 0})"), request(2, "r7", "GetPath", "{}")});
  const RequestWrites& path = sink.served_requests.at(1).second;
  ASSERT_EQ(path.answers.at(0).op, AnswerOp::SetPath) << path.answers[0].params.dump();
  EXPECT_EQ(path.answers[0].params["waypoints"][0], Json::parse("[2, 2]"));
  EXPECT_EQ(robots.at("r7").open_task->state, TaskState::Active);
}

}  // namespace
}  // namespace fleetmap::fakes
