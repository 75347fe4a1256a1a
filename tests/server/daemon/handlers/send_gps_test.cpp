// SendGPS (SPEC 5.2): the fix, with map coordinates when the map is georeferenced; OpAck.
#include <gtest/gtest.h>

#include "common/gis/geo_transform.h"
#include "tests/server/daemon/fake_stores.h"

namespace fleetmap::fakes {
namespace {

TEST(SendGps, StoresTheFixWithoutMapCoordinatesOnAMapWithoutGeoreference) {
  Bench b;
  const RequestWrites w = b.send("SendGPS", R"({"lat": 40.4, "lon": -3.7})");
  ASSERT_EQ(w.answers.size(), 1u);
  EXPECT_EQ(w.answers[0].op, AnswerOp::OpAck);
  ASSERT_EQ(w.fixes.size(), 1u);
  EXPECT_EQ(w.fixes[0].fix.lat, 40.4);
  EXPECT_EQ(w.fixes[0].fix.lon, -3.7);
  EXPECT_FALSE(w.fixes[0].map_xy);
}

TEST(SendGps, OnAGeoreferencedMapTheFixGetsMapCoordinates) {
  Bench b;
  MapInfo& info = b.maps.maps.at(1).first;
  info.georef = georef_from_origin(40.0, -3.0, 0);
  // 0.001 deg north of the origin: about 111 m along +y with the x axis heading east.
  const RequestWrites w = b.send("SendGPS", R"({"lat": 40.001, "lon": -3.0})");
  ASSERT_EQ(w.fixes.size(), 1u);
  ASSERT_TRUE(w.fixes[0].map_xy);
  EXPECT_NEAR(w.fixes[0].map_xy->x, 0, 0.5);
  EXPECT_NEAR(w.fixes[0].map_xy->y, 111.0, 1.0);
}

TEST(SendGps, MalformedParamsGetBadParamsAndNoFix) {
  for (const char* params : {R"({"lat": 40})", R"({"lat": 91, "lon": 0})", R"({"lat": "40", "lon": 0})"}) {
    Bench b;
    const RequestWrites w = b.send("SendGPS", params);
    EXPECT_EQ(error_code(w), "bad_params") << params;
    EXPECT_TRUE(w.fixes.empty()) << params;
  }
}

}  // namespace
}  // namespace fleetmap::fakes
