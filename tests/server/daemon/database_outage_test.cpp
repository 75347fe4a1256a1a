// DatabaseOutage (server/daemon/database_outage.h): while the database is down the
// process logs one line per back-off step, whoever tries; the schedule is checked
// against times written out here, not against the class's own arithmetic.
#include "server/daemon/database_outage.h"

#include <vector>

#include <gtest/gtest.h>

namespace fleetmap {
namespace {

using Clock = DatabaseOutage::Clock;

Clock::time_point at(double s) {
  return Clock::time_point{} + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(s));
}

TEST(DatabaseOutage, ThreeThreadsTryingForTwentySecondsLogOncePerStep) {
  DatabaseOutage o;
  // Three threads (two workers and the stall guard) each try every 0.3 s.
  std::vector<double> logged;
  int attempts = 0;
  for (int i = 0; i < 67; ++i)
    for (int thread = 0; thread < 3; ++thread, ++attempts) {
      const double t = 0.3 * i + 0.01 * thread;
      if (o.report(at(t))) logged.push_back(t);
    }
  // The first failure at once; then the first attempt after 0.1, 0.2, 0.4, 0.8, 1.6,
  // 3.2, 5, 5 s, each counted from the line before: 0 + 0.1 -> 0.3, + 0.2 -> 0.6,
  // + 0.4 -> 1.2, + 0.8 -> 2.1, + 1.6 -> 3.9, + 3.2 -> 7.2, + 5 -> 12.3, + 5 -> 17.4.
  const std::vector<double> expected = {0, 0.3, 0.6, 1.2, 2.1, 3.9, 7.2, 12.3, 17.4};
  ASSERT_EQ(logged.size(), expected.size()) << attempts << " attempts";
  for (size_t i = 0; i < expected.size(); ++i) EXPECT_NEAR(logged[i], expected[i], 1e-9) << i;
}

TEST(DatabaseOutage, AConnectionEndsTheOutageAndTheNextFailureLogsAtOnce) {
  DatabaseOutage o;
  EXPECT_FALSE(o.end());  // nothing was down
  EXPECT_TRUE(o.report(at(0)));
  EXPECT_FALSE(o.report(at(0.05)));
  EXPECT_TRUE(o.end());
  EXPECT_FALSE(o.end());
  EXPECT_TRUE(o.report(at(0.06)));  // a new outage: its first line at once
  EXPECT_FALSE(o.report(at(0.1)));  // and its steps start again at 0.1 s
  EXPECT_TRUE(o.report(at(0.17)));
}

TEST(RetryBackoff, WaitsDoubleFromATenthOfASecondToFiveAndReset) {
  RetryBackoff b;
  const std::vector<double> expected = {0.1, 0.2, 0.4, 0.8, 1.6, 3.2, 5.0, 5.0};
  for (double e : expected) EXPECT_DOUBLE_EQ(b.next_wait_s(), e);
  b.reset();
  EXPECT_DOUBLE_EQ(b.next_wait_s(), 0.1);
}

}  // namespace
}  // namespace fleetmap
