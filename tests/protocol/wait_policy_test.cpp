// WaitPolicy (protocol/wait_policy.h): the gap between polls while an answer is due, and
// its settings.
#include "protocol/wait_policy.h"

#include <stdexcept>

#include <gtest/gtest.h>

namespace fleetmap {
namespace {

TEST(WaitPolicy, GapIsAFractionOfTheWaitWithinItsBounds) {
  WaitPolicy p;
  p.min_ms = 2;
  p.max_ms = 40;
  p.backoff = 0.25;
  EXPECT_EQ(p.answer_gap_ms(0), 2);      // at first: the floor
  EXPECT_EQ(p.answer_gap_ms(4), 2);      // 1 ms would be below it
  EXPECT_EQ(p.answer_gap_ms(20), 5);     // a quarter of 20 ms
  EXPECT_EQ(p.answer_gap_ms(1000), 40);  // a slow server: capped, not 250 ms
  EXPECT_EQ(p.answer_gap_ms(-3), 2);     // a clock step back is no wait
  p.backoff = 0;                         // fixed interval
  EXPECT_EQ(p.answer_gap_ms(1000), 2);
}

TEST(WaitPolicy, SettingsApplyTheirKeysOnlyAndRefuseBadValues) {
  WaitPolicy p;
  p.apply({{"wait_first_poll_ms", "0.5"}, {"wait_min_ms", "3"}, {"wait_max_ms", "30"}, {"wait_backoff", "0.2"},
           {"wait_idle_ms", "100"}, {"user", "r1"}});
  EXPECT_EQ(p.first_poll_ms, 0.5);
  EXPECT_EQ(p.min_ms, 3);
  EXPECT_EQ(p.max_ms, 30);
  EXPECT_EQ(p.backoff, 0.2);
  EXPECT_EQ(p.idle_ms, 100);
  const WaitPolicy before = p;
  EXPECT_THROW(p.apply({{"wait_min_ms", "-1"}}), std::invalid_argument);
  EXPECT_THROW(p.apply({{"wait_idle_ms", "5ms"}}), std::invalid_argument);
  try {
    p.apply({{"wait_min_ms", "60"}});
    ADD_FAILURE() << "min above max accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("wait_max_ms"), std::string::npos) << e.what();
  }
  // A refused setting changes nothing.
  EXPECT_EQ(p.min_ms, before.min_ms);
  EXPECT_EQ(p.idle_ms, before.idle_ms);
}

}  // namespace
}  // namespace fleetmap
