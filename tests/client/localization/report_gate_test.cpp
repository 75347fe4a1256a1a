#include "client/localization/report_gate.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace fleetmap::localization {
namespace {

TEST(ReportGate, ReportsOnlyOnceTheCloudHoldsForTheWholeStreak) {
  ReportGate gate(3);
  EXPECT_FALSE(gate.update(true));
  EXPECT_FALSE(gate.update(true));
  // A scan that spreads the cloud again, or finds a look-alike place, starts over.
  EXPECT_FALSE(gate.update(false));
  EXPECT_FALSE(gate.update(true));
  EXPECT_FALSE(gate.update(true));
  EXPECT_TRUE(gate.update(true));
  EXPECT_TRUE(gate.update(true));
  gate.reset();
  EXPECT_FALSE(gate.update(true));
}

TEST(ReportGate, OneUpdateReportsAtTheFirstAndNoneIsRefused) {
  ReportGate first(1);
  EXPECT_FALSE(first.update(false));
  EXPECT_TRUE(first.update(true));
  EXPECT_THROW(ReportGate(0), std::invalid_argument);
  EXPECT_EQ(ReportGate().updates(), 3);
}

}  // namespace
}  // namespace fleetmap::localization
