// SendImage (SPEC 5.2): the image bytes with pose and object, within max_image_bytes; OpAck.
#include <gtest/gtest.h>

#include "tests/server/daemon/fake_stores.h"

namespace fleetmap::fakes {
namespace {

TEST(SendImage, StoresTheImageWithItsPoseAndObject) {
  Bench b;
  const RequestWrites w = b.send("SendImage", R"({"x": 1, "y": 2, "object_id": 9, "format": "jpeg"})", "JPEGDATA");
  ASSERT_EQ(w.answers.size(), 1u);
  EXPECT_EQ(w.answers[0].op, AnswerOp::OpAck);
  ASSERT_EQ(b.records.images.size(), 1u);
  EXPECT_EQ(b.records.images[0].robot_id, 7u);
  EXPECT_EQ(b.records.images[0].data, "JPEGDATA");
  EXPECT_EQ(b.records.images[0].p.object_id, 9);
  EXPECT_EQ(b.records.images[0].p.format, "jpeg");
  EXPECT_EQ(b.records.images[0].at, "2026-11-28 07:00:01.000000");
}

TEST(SendImage, NoBytesIsBadParamsTooManyIsPayloadTooLarge) {
  Bench b;
  b.config.max_image_bytes = 4;
  const char* p = R"({"x": 1, "y": 2, "object_id": 9, "format": "jpeg"})";
  EXPECT_EQ(error_code(b.send("SendImage", p)), "bad_params");
  EXPECT_EQ(error_code(b.send("SendImage", p, "")), "bad_params");
  const RequestWrites w = b.send("SendImage", p, "12345");
  EXPECT_EQ(error_code(w), "payload_too_large");
  EXPECT_NE(w.answers[0].params["message"].get<std::string>().find("at most 4 bytes, got 5"), std::string::npos);
  EXPECT_TRUE(b.records.images.empty());
  EXPECT_EQ(b.send("SendImage", p, "1234").answers.at(0).op, AnswerOp::OpAck);
}

TEST(SendImage, MalformedParamsGetBadParams) {
  Bench b;
  EXPECT_EQ(error_code(b.send("SendImage", R"({"x": 1, "format": "jpeg"})", "x")), "bad_params");
  EXPECT_TRUE(b.records.images.empty());
}

}  // namespace
}  // namespace fleetmap::fakes
