// Alive (SPEC 5.2): no answer; malformed params get an Error like any other op.
#include <gtest/gtest.h>

#include "tests/server/daemon/fake_stores.h"

namespace fleetmap::fakes {
namespace {

TEST(Alive, GetsNoAnswerAndWritesNothing) {
  Bench b;
  const RequestWrites w = b.send("Alive", "{}");
  EXPECT_TRUE(w.answers.empty());
  EXPECT_TRUE(w.poses.empty());
  EXPECT_FALSE(b.records.wrote_anything());
}

TEST(Alive, ParamsThatAreNoObjectGetBadJson) {
  for (const char* params : {"[]", "1", "\"x\"", "{", "null"}) {
    Bench b;
    EXPECT_EQ(error_code(b.send("Alive", params)), "bad_json") << params;
  }
}

TEST(Alive, BeforeReadyIsNotRegistered) {
  Bench b;
  b.robot().magic.reset();
  EXPECT_EQ(error_code(b.send("Alive", "{}")), "not_registered");
}

}  // namespace
}  // namespace fleetmap::fakes
