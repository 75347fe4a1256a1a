// Sessions (server/web/http/session_store.h) and the login throttle
// (login_throttle.h), on a clock the test moves.
#include "server/web/http/session_store.h"

#include <gtest/gtest.h>

#include "server/web/http/login_throttle.h"

namespace fleetmap::web {
namespace {
using std::chrono::seconds;

TEST(SessionStore, OpensFindsAndCloses) {
  SessionStore store(seconds(60), 10);
  const auto t0 = Clock::now();
  auto s = store.open({"fleetmap_operator", WebRole::Operator}, nullptr, t0);
  EXPECT_EQ(s->id.size(), 64u);
  EXPECT_EQ(s->csrf.size(), 64u);
  EXPECT_NE(s->id, s->csrf);
  EXPECT_EQ(store.find(s->id, t0), s);
  EXPECT_EQ(store.find(s->id.substr(0, 63), t0), nullptr);
  EXPECT_EQ(store.find("", t0), nullptr);
  store.close(s->id);
  EXPECT_EQ(store.find(s->id, t0), nullptr);
}

TEST(SessionStore, IdleSessionsExpireAndUseKeepsThemAlive) {
  SessionStore store(seconds(60), 10);
  const auto t0 = Clock::now();
  auto used = store.open({"a", WebRole::Operator}, nullptr, t0);
  auto idle = store.open({"b", WebRole::Inspector}, nullptr, t0);
  EXPECT_EQ(store.find(used->id, t0 + seconds(50)), used);
  EXPECT_EQ(store.find(used->id, t0 + seconds(100)), used);  // 50 s since its last use
  EXPECT_EQ(store.find(idle->id, t0 + seconds(100)), nullptr);
  EXPECT_EQ(store.size(), 1u);
}

TEST(SessionStore, MaxSessions) {
  SessionStore store(seconds(60), 2);
  const auto t0 = Clock::now();
  store.open({"a", WebRole::Operator}, nullptr, t0);
  store.open({"b", WebRole::Operator}, nullptr, t0);
  try {
    store.open({"c", WebRole::Operator}, nullptr, t0);
    FAIL() << "a third session beyond max_sessions";
  } catch (const ApiError& e) {
    EXPECT_EQ(e.status(), 503);
  }
  // Once the others are idle too long, there is room again.
  EXPECT_NO_THROW(store.open({"c", WebRole::Operator}, nullptr, t0 + seconds(61)));
  EXPECT_EQ(store.size(), 1u);
}

TEST(LoginThrottle, FiveFailuresWithinAMinuteBlockForAMinute) {
  LoginThrottle t;
  const auto t0 = LoginThrottle::Clock::now();
  for (int i = 0; i < 4; ++i) t.failed("10.0.0.1", t0 + seconds(i));
  EXPECT_FALSE(t.blocked("10.0.0.1", t0 + seconds(5)));
  t.failed("10.0.0.1", t0 + seconds(5));
  EXPECT_TRUE(t.blocked("10.0.0.1", t0 + seconds(6)));
  EXPECT_FALSE(t.blocked("10.0.0.2", t0 + seconds(6))) << "other addresses are not blocked";
  EXPECT_TRUE(t.blocked("10.0.0.1", t0 + seconds(64)));
  EXPECT_FALSE(t.blocked("10.0.0.1", t0 + seconds(66)));
}

TEST(LoginThrottle, FailuresSpreadOverMoreThanAMinuteDoNotBlock) {
  LoginThrottle t;
  const auto t0 = LoginThrottle::Clock::now();
  for (int i = 0; i < 10; ++i) t.failed("10.0.0.1", t0 + seconds(20 * i));
  EXPECT_FALSE(t.blocked("10.0.0.1", t0 + seconds(181)));
}

TEST(LoginThrottle, SuccessForgetsFailures) {
  LoginThrottle t;
  const auto t0 = LoginThrottle::Clock::now();
  for (int i = 0; i < 4; ++i) t.failed("10.0.0.1", t0);
  t.succeeded("10.0.0.1");
  t.failed("10.0.0.1", t0);
  EXPECT_FALSE(t.blocked("10.0.0.1", t0));
}

}  // namespace
}  // namespace fleetmap::web
