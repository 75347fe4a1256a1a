// The feed's coalescing (server/web/http/push_queue.h, push_hub.h): one frame in flight
// per client, the latest state per robot kept meanwhile, a stalled client holding one
// state per robot however many updates pass, and others receiving all the while.
#include "server/web/http/push_queue.h"

#include <gtest/gtest.h>

#include "server/web/http/push_hub.h"

namespace fleetmap::web {
namespace {

nlohmann::json robot(const std::string& name, double x) { return {{"name", name}, {"x", x}}; }

nlohmann::json parse(const std::optional<std::string>& frame) {
  EXPECT_TRUE(frame.has_value());
  return frame ? nlohmann::json::parse(*frame) : nlohmann::json();
}

TEST(PushQueue, HelloFirstThenRobotsThenTasks) {
  PushQueue q;
  q.tasks({{{"id", 7}, {"state", "assigned"}}});
  q.robots({robot("r1", 1)});
  q.hello({{"type", "hello"}, {"user", "op"}});
  EXPECT_EQ(parse(q.take())["type"], "hello");
  EXPECT_FALSE(q.take()) << "a second frame while the first is in flight";
  q.sent();
  const auto robots = parse(q.take());
  EXPECT_EQ(robots["type"], "robots");
  EXPECT_EQ(robots["robots"].size(), 1u);
  q.sent();
  const auto tasks = parse(q.take());
  EXPECT_EQ(tasks["type"], "tasks");
  EXPECT_EQ(tasks["tasks"][0]["id"], 7);
  q.sent();
  EXPECT_FALSE(q.take());
  EXPECT_FALSE(q.in_flight());
}

TEST(PushQueue, CoalescesTheLatestStatePerRobot) {
  PushQueue q;
  q.robots({robot("r1", 0)});
  ASSERT_TRUE(q.take());  // in flight now; what follows waits
  for (int i = 1; i <= 1000; ++i) q.robots({robot("r1", i), robot("r2", -i)});
  q.tasks({{{"id", 1}, {"state", "assigned"}}});
  q.tasks({{{"id", 1}, {"state", "active"}}});
  EXPECT_EQ(q.pending_robots(), 2u);
  EXPECT_EQ(q.pending_tasks(), 1u);
  q.sent();
  const auto robots = parse(q.take());
  ASSERT_EQ(robots["robots"].size(), 2u);
  for (const auto& r : robots["robots"]) EXPECT_EQ(std::abs(r["x"].get<double>()), 1000) << r.dump();
  q.sent();
  EXPECT_EQ(parse(q.take())["tasks"][0]["state"], "active");
}

TEST(PushQueue, AFirstRobotsMessageEvenWhenThereAreNone) {
  PushQueue q;
  q.robots({}, true);
  const auto m = parse(q.take());
  EXPECT_EQ(m["type"], "robots");
  EXPECT_TRUE(m["robots"].empty());
  q.sent();
  q.robots({});
  EXPECT_FALSE(q.take()) << "later empty updates send nothing";
}

// A client whose frames leave only when the test says so, like a socket that stalls.
class FakeClient : public PushClient {
 public:
  void push(const FeedUpdate& u, bool first) override {
    queue.robots(u.robots, first);
    queue.tasks(u.tasks);
  }
  // Everything the client would receive if it read now: the frames, each sent.
  std::vector<nlohmann::json> drain() {
    std::vector<nlohmann::json> out;
    while (auto f = queue.take()) {
      out.push_back(nlohmann::json::parse(*f));
      queue.sent();
    }
    return out;
  }
  PushQueue queue;
};

TEST(PushHub, NewClientsGetEveryRobotFirst) {
  PushHub hub;
  hub.publish({{robot("r1", 1), robot("r2", 2)}, {}});
  hub.publish({{robot("r1", 5)}, {}});
  auto c = std::make_shared<FakeClient>();
  hub.subscribe(c);
  const auto frames = c->drain();
  ASSERT_EQ(frames.size(), 1u);
  ASSERT_EQ(frames[0]["robots"].size(), 2u);
  EXPECT_EQ(frames[0]["robots"][0]["x"], 5);  // r1's latest state
  hub.publish({{robot("r2", 9)}, {}});
  const auto later = c->drain();
  ASSERT_EQ(later.size(), 1u);
  ASSERT_EQ(later[0]["robots"].size(), 1u) << "later messages hold only the robots that changed";
  EXPECT_EQ(later[0]["robots"][0]["name"], "r2");
}

TEST(PushHub, AStalledClientNeitherGrowsNorDelaysTheOthers) {
  PushHub hub;
  hub.publish({{robot("r0", -1)}, {}});  // the feed's first poll
  auto stalled = std::make_shared<FakeClient>();
  auto reader = std::make_shared<FakeClient>();
  hub.subscribe(stalled);
  hub.subscribe(reader);
  ASSERT_TRUE(stalled->queue.take());  // its first frame never completes
  reader->drain();
  size_t received = 0;
  for (int i = 0; i < 5000; ++i) {
    hub.publish({{robot("r" + std::to_string(i % 10), i)}, {{{"id", i % 3}, {"state", "active"}}}});
    for (const auto& f : reader->drain())
      if (f["type"] == "robots") received += f["robots"].size();
  }
  EXPECT_EQ(received, 5000u) << "the reading client got every change";
  EXPECT_EQ(stalled->queue.pending_robots(), 10u) << "one state per robot, however long it stalls";
  EXPECT_EQ(stalled->queue.pending_tasks(), 3u);
  stalled->queue.sent();
  const auto caught_up = stalled->drain();
  ASSERT_EQ(caught_up.size(), 2u);
  EXPECT_EQ(caught_up[0]["robots"][9]["x"], 4999);
}

TEST(PushHub, AClientBeforeTheFirstPollGetsEveryRobotWithIt) {
  PushHub hub;
  auto early = std::make_shared<FakeClient>();
  hub.subscribe(early);
  EXPECT_TRUE(early->drain().empty()) << "nothing to tell before the feed's first poll";
  hub.publish({{robot("r1", 1), robot("r2", 2)}, {}});
  const auto frames = early->drain();
  ASSERT_EQ(frames.size(), 1u);
  EXPECT_EQ(frames[0]["robots"].size(), 2u);
  // An empty fleet: the first message still comes, empty.
  PushHub empty;
  auto c = std::make_shared<FakeClient>();
  empty.subscribe(c);
  empty.publish({});
  const auto none = c->drain();
  ASSERT_EQ(none.size(), 1u);
  EXPECT_TRUE(none[0]["robots"].empty());
}

TEST(PushHub, DropsClientsThatAreGone) {
  PushHub hub;
  auto c = std::make_shared<FakeClient>();
  hub.subscribe(c);
  EXPECT_EQ(hub.clients(), 1u);
  c.reset();
  hub.publish({{robot("r1", 1)}, {}});
  EXPECT_EQ(hub.clients(), 0u);
}

}  // namespace
}  // namespace fleetmap::web
