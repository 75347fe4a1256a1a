// SetObject (SPEC 5.2): the report as it came, and on a robot with a map an observation
// of the map's scene that expires object_ttl_s after this sighting; OpAck.
#include <gtest/gtest.h>

#include "tests/server/daemon/fake_stores.h"

namespace fleetmap::fakes {
namespace {

TEST(SetObject, RecordsTheReportAndTheMapsObservation) {
  Bench b;
  b.config.object_ttl_s = 60;
  const RequestWrites w = b.send("SetObject", R"({"x": 4, "y": 5, "object": "pallet"})");
  ASSERT_EQ(w.answers.size(), 1u);
  EXPECT_EQ(w.answers[0].op, AnswerOp::OpAck);
  ASSERT_EQ(b.records.objects.size(), 1u);
  EXPECT_EQ(b.records.objects[0].map_id, 1u);
  EXPECT_EQ(b.records.objects[0].p.object, "pallet");
  ASSERT_EQ(b.records.observations.size(), 1u);
  EXPECT_EQ(b.records.observations[0].map_id, 1u);
  EXPECT_EQ(b.records.observations[0].robot_id, 7u);
  EXPECT_EQ(b.records.observations[0].p.x, 4);
  EXPECT_EQ(b.records.observations[0].ttl_s, 60);
  EXPECT_EQ(b.records.observations[0].at, b.records.objects[0].at);
}

TEST(SetObject, ARobotWithoutAMapOnlyReports) {
  Bench b;
  b.robot().map_id.reset();
  EXPECT_EQ(b.send("SetObject", R"({"x": 4, "y": 5, "object": "pallet"})").answers.at(0).op, AnswerOp::OpAck);
  ASSERT_EQ(b.records.objects.size(), 1u);
  EXPECT_FALSE(b.records.objects[0].map_id);
  EXPECT_TRUE(b.records.observations.empty());
}

TEST(SetObject, MalformedParamsGetBadParamsAndRecordNothing) {
  for (const char* params : {R"({"x": 4, "y": 5})", R"({"x": 4, "y": 5, "object": ""})",
                             R"({"x": 4, "y": 5, "object": 3})", R"({"x": "4", "y": 5, "object": "a"})"}) {
    Bench b;
    EXPECT_EQ(error_code(b.send("SetObject", params)), "bad_params") << params;
    EXPECT_FALSE(b.records.wrote_anything()) << params;
  }
}

}  // namespace
}  // namespace fleetmap::fakes
