// WKT polygons (common/io/wkt.h): what the semantic layer stores and operators type.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "common/io/wkt.h"

namespace fleetmap {
namespace {

// The message of the invalid_argument that parse_polygon_wkt throws for wkt.
std::string refusal(const std::string& wkt) {
  try {
    parse_polygon_wkt(wkt);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(accepted)";
}

TEST(Wkt, ParsesARingAndDropsTheClosingVertex) {
  EXPECT_EQ(parse_polygon_wkt("POLYGON((0 0,2 0,2 1,0 0))"), (Polygon{{0, 0}, {2, 0}, {2, 1}}));
  // The closing vertex is optional, the word's case and the blanks are free.
  EXPECT_EQ(parse_polygon_wkt("  polygon ( ( -1.5 2e1 , 3 -4 ,5 6 ) )  "), (Polygon{{-1.5, 20}, {3, -4}, {5, 6}}));
  EXPECT_EQ(parse_polygon_wkt("Polygon((0 0,1 0,1 1,0 1))"), (Polygon{{0, 0}, {1, 0}, {1, 1}, {0, 1}}));
}

TEST(Wkt, WritesTheClosedRing) {
  EXPECT_EQ(polygon_to_wkt({{0, 0}, {2, 0}, {2, 1}}), "POLYGON((0 0,2 0,2 1,0 0))");
  EXPECT_EQ(polygon_to_wkt({{-1.5, 20}, {3, -4}, {5, 6}}), "POLYGON((-1.5 20,3 -4,5 6,-1.5 20))");
}

TEST(Wkt, ShortestRoundTripNumbers) {
  // 0.1 + 0.2 is not 0.3: 17 digits are needed, and no more than needed elsewhere.
  const Polygon ring{{0.1, 0.30000000000000004}, {2, 0}, {1e-7, 123456.789}};
  const std::string text = polygon_to_wkt(ring);
  EXPECT_EQ(text, "POLYGON((0.1 0.30000000000000004,2 0,1e-07 123456.789,0.1 0.30000000000000004))");
  EXPECT_EQ(parse_polygon_wkt(text), ring);
}

TEST(Wkt, RoundTripKeepsEveryBit) {
  const Polygon ring{{1.0 / 3, -2.0 / 3}, {1e300, 1e-300}, {-0.0, 7.25}};
  const Polygon back = parse_polygon_wkt(polygon_to_wkt(ring));
  ASSERT_EQ(back.size(), ring.size());
  for (size_t i = 0; i < ring.size(); ++i) {
    EXPECT_EQ(back[i].x, ring[i].x) << i;
    EXPECT_EQ(back[i].y, ring[i].y) << i;
  }
}

TEST(Wkt, RefusesUnclosedParentheses) {
  EXPECT_NE(refusal("POLYGON((0 0,1 0,1 1").find("expected ',' or ')'"), std::string::npos) << refusal("POLYGON((0 0,1 0,1 1");
  EXPECT_NE(refusal("POLYGON((0 0,1 0,1 1)").find("expected '))'"), std::string::npos);
  EXPECT_NE(refusal("POLYGON(0 0,1 0,1 1)").find("expected '(('"), std::string::npos);
}

TEST(Wkt, RefusesTooFewVertices) {
  for (const char* wkt : {"POLYGON((0 0))", "POLYGON((0 0,1 0))", "POLYGON((0 0,1 0,0 0))"})
    EXPECT_NE(refusal(wkt).find("expected at least 3 vertices"), std::string::npos) << wkt << ": " << refusal(wkt);
}

TEST(Wkt, RefusesNonFiniteNumbers) {
  for (const char* wkt : {"POLYGON((0 0,1 nan,1 1))", "POLYGON((0 0,inf 0,1 1))", "POLYGON((0 0,1 1e999,1 1))",
                          "POLYGON((0 0,1 x,1 1))", "POLYGON((0 0,1,1 1))"})
    EXPECT_NE(refusal(wkt).find("expected a finite number"), std::string::npos) << wkt << ": " << refusal(wkt);
}

TEST(Wkt, RefusesGarbageAfterTheRing) {
  const std::string m = refusal("POLYGON((0 0,1 0,1 1))x");
  EXPECT_NE(m.find("expected nothing after '))'"), std::string::npos) << m;
  EXPECT_NE(m.find("got 'POLYGON((0 0,1 0,1 1))x'"), std::string::npos) << m;  // names the input
}

TEST(Wkt, RefusesHoles) {
  const std::string m = refusal("POLYGON((0 0,4 0,4 4,0 0),(1 1,2 1,2 2,1 1))");
  EXPECT_NE(m.find("expected one ring"), std::string::npos) << m;
}

TEST(Wkt, RefusesOtherGeometryTypes) {
  for (const char* wkt : {"MULTIPOLYGON(((0 0,1 0,1 1,0 0)))", "LINESTRING(0 0,1 1)", "POINT(1 2)", "POLYGONS((0 0,1 0,1 1))"})
    EXPECT_NE(refusal(wkt).find("expected the word POLYGON"), std::string::npos) << wkt << ": " << refusal(wkt);
}

TEST(Wkt, RefusesEmptyInput) {
  EXPECT_NE(refusal("").find("expected the word POLYGON"), std::string::npos);
  EXPECT_NE(refusal("   ").find("expected the word POLYGON"), std::string::npos);
  EXPECT_NE(refusal("POLYGON EMPTY").find("expected '(('"), std::string::npos);
  EXPECT_NE(refusal("POLYGON(())").find("expected a finite number"), std::string::npos);
}

}  // namespace
}  // namespace fleetmap
