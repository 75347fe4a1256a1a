// common/io/map_geojson.*: the GeoJSON (RFC 7946) writer. The output is parsed back with
// nlohmann::json and compared with the model, numbers bit for bit.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>

#include "common/io/map_geojson.h"
#include "common/map/map_validation.h"
#include "common/map/ramp.h"

namespace fleetmap {
namespace {

using nlohmann::json;

// Quotes, a backslash and non-ASCII UTF-8 (2-, 3- and 4-byte sequences).
const std::string kTrickySemantic = "b\xC3\xA2timent \"A\" \\ \xE6\x9D\xB1 \xF0\x9F\xA4\x96";

// A closed polygon with awkward doubles, stairs (seed 000 Fig. 1) and a ramp (ramp.h).
Map sample_map() {
  Map m;
  m.border = {0, 20, 30, 0};
  const double third = 1.0 / 3, x = 0.1 + 0.2, y = std::nextafter(4.9, 5.0);
  Obstacle wall{1, ShapeType::ClosedPolygon, kTrickySemantic, {}, {}};
  wall.segments = {{{x, 1.3}, {5.7, 1.3}, 2.5, 0, "wall,brick", ""},
                   {{5.7, 1.3}, {5.7, y}, 2.5, 1, "door,glass", "main entrance, 50% open"},
                   {{5.7, y}, {third, y}, 2.5, 0, kTrickySemantic, ""},
                   {{third, y}, {x, 1.3}, 1e-3, 0, "", ""}};
  Obstacle stairs{2, ShapeType::Stairs, "stairs,north", {}, {}};
  stairs.segments = {{{14, 10.3}, {10, 10.3}, 0.51, 0, "step", ""},
                     {{14, 10.6}, {10, 10.6}, 0.34, 0, "step", ""},
                     {{14, 10.9}, {10, 10.9}, 0.17, 0, "step", ""},
                     {{10, 10}, {14, 10}, 0, 0, "landing", ""}};
  Obstacle ramp{3, ShapeType::Ramp, "ramp,concrete," + ramp_tokens(-0.125, 0, 1, {20, 5}), {}, {}};
  ramp.segments = {{{20, 5}, {28, 5}, 0, 1, "edge", ""},
                   {{28, 5}, {28, 9}, 0, 1, "edge", ""},
                   {{28, 9}, {20, 9}, 0, 1, "edge", ""},
                   {{20, 9}, {20, 5}, 0, 1, "edge", ""}};
  m.obstacles = {wall, stairs, ramp};
  return m;
}

TEST(MapGeojson, SampleMapIsValid) { EXPECT_NO_THROW(validate_map(sample_map())); }

TEST(MapGeojson, IsAFeatureCollectionWithTheFrameAsForeignMember) {
  const Map m = sample_map();
  const json j = json::parse(write_geojson(m, "campus \"east\""));
  EXPECT_EQ(j.at("type"), "FeatureCollection");
  EXPECT_FALSE(j.contains("crs"));
  const json& f = j.at("fleetmap");
  EXPECT_EQ(f.at("map"), "campus \"east\"");
  EXPECT_EQ(f.at("frame"), "map");
  EXPECT_EQ(f.at("units"), "m");
  EXPECT_EQ(f.at("border"), json::array({0.0, 20.0, 30.0, 0.0}));
  ASSERT_TRUE(j.at("features").is_array());
  EXPECT_EQ(j.at("features").size(), m.segment_count() + 1);
  for (const json& feature : j.at("features")) {
    EXPECT_EQ(feature.at("type"), "Feature");
    EXPECT_TRUE(feature.at("geometry").is_object());
    EXPECT_TRUE(feature.at("properties").is_object());
  }
}

TEST(MapGeojson, BorderIsAClosedCounterClockwiseRing) {
  const json j = json::parse(write_geojson(sample_map()));
  size_t borders = 0;
  for (const json& feature : j.at("features")) {
    if (feature.at("properties").at("kind") != "border") continue;
    ++borders;
    EXPECT_EQ(feature.at("properties").size(), 1u);
    EXPECT_EQ(feature.at("geometry").at("type"), "Polygon");
    const json& rings = feature.at("geometry").at("coordinates");
    ASSERT_EQ(rings.size(), 1u);
    const json& ring = rings[0];
    ASSERT_EQ(ring.size(), 5u);
    EXPECT_EQ(ring.front(), ring.back());
    double twice_area = 0;  // shoelace: positive when counter-clockwise (y upwards)
    for (size_t i = 0; i + 1 < ring.size(); ++i)
      twice_area += ring[i][0].get<double>() * ring[i + 1][1].get<double>() -
                    ring[i + 1][0].get<double>() * ring[i][1].get<double>();
    EXPECT_DOUBLE_EQ(twice_area, 2 * 30 * 20);
    for (const json& p : ring) {
      EXPECT_TRUE(p[0] == 0.0 || p[0] == 30.0) << p;
      EXPECT_TRUE(p[1] == 0.0 || p[1] == 20.0) << p;
    }
  }
  EXPECT_EQ(borders, 1u);
}

TEST(MapGeojson, SegmentFeaturesMatchTheModelExactly) {
  const Map m = sample_map();
  const json j = json::parse(write_geojson(m));
  const json& features = j.at("features");
  size_t k = 0;
  for (const json& feature : features) {
    if (feature.at("properties").at("kind") == "segment") break;
    ++k;
  }
  for (const Obstacle& o : m.obstacles) {
    for (size_t i = 0; i < o.segments.size(); ++i, ++k) {
      SCOPED_TRACE("obstacle " + std::to_string(o.id) + " segment " + std::to_string(i + 1));
      ASSERT_LT(k, features.size());
      const Segment& s = o.segments[i];
      const json& g = features[k].at("geometry");
      EXPECT_EQ(g.at("type"), "LineString");
      const json& c = g.at("coordinates");
      ASSERT_EQ(c.size(), 2u);
      // Exact equality on purpose: the writer must round-trip every double.
      EXPECT_EQ(c[0][0].get<double>(), s.a.x);
      EXPECT_EQ(c[0][1].get<double>(), s.a.y);
      EXPECT_EQ(c[1][0].get<double>(), s.b.x);
      EXPECT_EQ(c[1][1].get<double>(), s.b.y);
      const json& p = features[k].at("properties");
      EXPECT_EQ(p.at("kind"), "segment");
      EXPECT_EQ(p.at("obstacle_id").get<int>(), o.id);
      EXPECT_EQ(p.at("st").get<int>(), static_cast<int>(o.type));
      EXPECT_EQ(p.at("shape").get<std::string>(), to_string(o.type));
      EXPECT_EQ(p.at("obstacle_semantic").get<std::string>(), o.semantic);
      EXPECT_EQ(p.at("segment").get<size_t>(), i + 1);
      EXPECT_EQ(p.at("h").get<double>(), s.h);
      EXPECT_EQ(p.at("in_out").get<int>(), s.in_out);
      EXPECT_EQ(p.at("semantic").get<std::string>(), s.semantic);
      EXPECT_EQ(p.contains("note"), !s.note.empty());
      if (!s.note.empty()) {
        EXPECT_EQ(p.at("note").get<std::string>(), s.note);
      }
    }
  }
  EXPECT_EQ(k, features.size());
}

TEST(MapGeojson, QuotesBackslashesAndUtf8Survive) {
  const std::string text = write_geojson(sample_map(), kTrickySemantic);
  EXPECT_NE(text.find("\xE6\x9D\xB1"), std::string::npos);  // written as UTF-8, not \u escapes
  const json j = json::parse(text);
  EXPECT_EQ(j.at("fleetmap").at("map").get<std::string>(), kTrickySemantic);
  const json& first = j.at("features")[1].at("properties");
  EXPECT_EQ(first.at("obstacle_semantic").get<std::string>(), kTrickySemantic);
  EXPECT_EQ(j.at("features")[3].at("properties").at("semantic").get<std::string>(), kTrickySemantic);
  EXPECT_EQ(j.at("features")[2].at("properties").at("note").get<std::string>(), "main entrance, 50% open");
}

TEST(MapGeojson, RandomDoublesRoundTrip) {
  std::mt19937_64 rng(20240607);
  std::uniform_real_distribution<double> coord(-1e7, 1e7), small(-1, 1);
  std::uniform_int_distribution<int> exponent(-30, 7);
  for (int n = 0; n < 2000; ++n) {
    const double ax = coord(rng), ay = small(rng) * std::pow(10.0, exponent(rng));
    const double bx = std::nextafter(ax, 1e300), by = 1.0 / (n + 3), h = small(rng) * 1000;
    Map m;
    m.border = {-1e7, 1e7, 1e7, -1e7};
    m.obstacles = {{n, ShapeType::OpenPolygon, "", {{{ax, ay}, {bx, by}, h, 0, "", ""}}, {}}};
    const json c = json::parse(write_geojson(m)).at("features")[1].at("geometry").at("coordinates");
    ASSERT_EQ(c[0][0].get<double>(), ax);
    ASSERT_EQ(c[0][1].get<double>(), ay);
    ASSERT_EQ(c[1][0].get<double>(), bx);
    ASSERT_EQ(c[1][1].get<double>(), by);
  }
}

TEST(MapGeojson, OneFeaturePerLine) {
  const Map m = sample_map();
  const std::string text = write_geojson(m);
  ASSERT_FALSE(text.empty());
  EXPECT_EQ(text.back(), '\n');
  size_t lines = 0;
  for (char c : text) lines += c == '\n';
  EXPECT_EQ(lines, m.segment_count() + 1 + 2);  // header line, features, closing line
}

TEST(MapGeojson, RejectsWhatJsonCannotHold) {
  Map m = sample_map();
  m.obstacles[1].segments[2].semantic = "bad \xC3(";
  try {
    write_geojson(m);
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("obstacle 2 segment 3"), std::string::npos) << e.what();
  }
  m = sample_map();
  m.obstacles[0].segments[0].h = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(write_geojson(m), std::invalid_argument);
}

}  // namespace
}  // namespace fleetmap
