// Ramps (ST 6, common/map/ramp.h) and stairs (ST 5, check_shape in common/map/map_validation.cpp)
// as encoded in docs/map-format.md.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "common/map/map_validation.h"
#include "common/map/map_window.h"
#include "common/map/ramp.h"
#include "common/io/seed_format.h"

namespace fleetmap {
namespace {

const std::string kExample = FLEETMAP_SOURCE_DIR "/maps/example-campus.map";

const Obstacle& find_type(const Map& m, ShapeType t) {
  for (const Obstacle& o : m.obstacles)
    if (o.type == t) return o;
  throw std::runtime_error("no obstacle of that type");
}

// The message of parse_ramp_surface's exception, or "" when it parses.
std::string ramp_error(std::string_view semantic) {
  try {
    parse_ramp_surface(semantic);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

// ---- ramps ------------------------------------------------------------------------

TEST(Ramp, ExampleMapSurfaceHeights) {
  const Map m = read_seed_file(kExample);
  const Obstacle& ramp = find_type(m, ShapeType::Ramp);
  EXPECT_EQ(ramp.semantic, "ramp,concrete,normal=-0.125:0:1,foot=8:10");
  const RampSurface s = ramp_surface(ramp);
  // normal (-0.125, 0, 1): the surface rises 0.125 m per metre along +x, from the foot
  // line x = 8 (z = 0) to x = 12 (z = 0.5): a 4 m ramp rising 0.5 m.
  EXPECT_EQ(s.gradient.x, 0.125);
  EXPECT_EQ(s.gradient.y, 0);
  EXPECT_EQ(s.foot, (Point{8, 10}));
  EXPECT_EQ(s.height_at({8, 10}), 0);
  EXPECT_EQ(s.height_at({8, 12}), 0);      // the whole lower edge is on the floor
  EXPECT_EQ(s.height_at({10, 11}), 0.25);  // 0.125 * (10 - 8)
  EXPECT_EQ(s.height_at({11.5, 10.5}), 0.4375);  // 0.125 * 3.5
  EXPECT_EQ(s.height_at({12, 10}), 0.5);   // top edge
  EXPECT_EQ(s.height_at({12, 12}), 0.5);
  // Every segment of a ramp has null height (planners ignore it, SPEC 7).
  for (const Segment& seg : ramp.segments) EXPECT_EQ(seg.h, 0);
}

TEST(Ramp, NormalScaleDoesNotMatter) {
  const RampSurface a = parse_ramp_surface("ramp,normal=-0.125:0:1,foot=8:10");
  const RampSurface b = parse_ramp_surface("normal=-0.5:0:4,foot=8:10,ramp");
  EXPECT_EQ(a, b);
}

TEST(Ramp, SlopeAlongBothAxes) {
  // normal (0.1, -0.2, 2): gradient (-0.05, 0.1); at (1, 3) from foot (2, 1): -0.05*-1 + 0.1*2.
  const RampSurface s = parse_ramp_surface("normal=0.1:-0.2:2,foot=2:1");
  EXPECT_DOUBLE_EQ(s.gradient.x, -0.05);
  EXPECT_DOUBLE_EQ(s.gradient.y, 0.1);
  EXPECT_DOUBLE_EQ(s.height_at({1, 3}), 0.25);
}

TEST(Ramp, TokensRoundTrip) {
  EXPECT_EQ(ramp_tokens(-0.125, 0, 1, {8, 10}), "normal=-0.125:0:1,foot=8:10");
  const RampSurface s = parse_ramp_surface("ramp," + ramp_tokens(0.3, -0.1, 1.7, {-2.5, 1e-3}));
  EXPECT_DOUBLE_EQ(s.gradient.x, -0.3 / 1.7);
  EXPECT_DOUBLE_EQ(s.gradient.y, 0.1 / 1.7);
  EXPECT_EQ(s.foot, (Point{-2.5, 1e-3}));
}

TEST(Ramp, TokenParseErrors) {
  EXPECT_NE(ramp_error("ramp,foot=8:10").find("expected 'normal=NX:NY:NZ'"), std::string::npos);
  EXPECT_NE(ramp_error("ramp,normal=-0.125:0:1").find("expected 'foot=X:Y'"), std::string::npos);
  EXPECT_NE(ramp_error("").find("normal=NX:NY:NZ"), std::string::npos);
  // Wrong number of numbers.
  EXPECT_NE(ramp_error("normal=-0.125:1,foot=8:10").find("(3 numbers), got 'normal=-0.125:1'"), std::string::npos);
  EXPECT_NE(ramp_error("normal=0:0:1:1,foot=8:10").find("3 numbers"), std::string::npos);
  EXPECT_NE(ramp_error("normal=0:0:1,foot=8").find("(2 numbers), got 'foot=8'"), std::string::npos);
  EXPECT_NE(ramp_error("normal=0:0:1,foot=8:10:0").find("2 numbers"), std::string::npos);
  // Not numbers, empty fields, non-finite values, blanks.
  for (const char* bad : {"normal=a:0:1,foot=8:10", "normal=:0:1,foot=8:10", "normal=0::1,foot=8:10",
                          "normal=,foot=8:10", "normal=nan:0:1,foot=8:10", "normal=0:0:inf,foot=8:10",
                          "normal=0:0:1,foot=8:", "normal=0:0:1,foot=1e999:0", "normal=0 :0:1,foot=8:10",
                          "normal=0:0:1x,foot=8:10"})
    EXPECT_NE(ramp_error(bad).find("with finite numbers, got"), std::string::npos) << bad << ": " << ramp_error(bad);
  // The normal must point up.
  EXPECT_NE(ramp_error("normal=0.1:0:0,foot=0:0").find("NZ > 0"), std::string::npos);
  EXPECT_NE(ramp_error("normal=0.1:0:-1,foot=0:0").find("NZ > 0"), std::string::npos);
  // A token is "name=" at the start of a comma-separated token, nothing else.
  EXPECT_NE(ramp_error("abnormal=0:0:1,foot=0:0").find("expected 'normal=NX:NY:NZ'"), std::string::npos);
  EXPECT_EQ(ramp_error("normal=0:0:1,foot=0:0"), "");  // a flat ramp is allowed
}

Obstacle rect_ramp(const std::string& semantic, double x0, double y0, double x1, double y1) {
  Obstacle o;
  o.id = 7;
  o.type = ShapeType::Ramp;
  o.semantic = semantic;
  const Point p[4] = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
  for (int i = 0; i < 4; ++i) o.segments.push_back(Segment{p[i], p[(i + 1) % 4], 0, 1, "edge", ""});
  return o;
}

TEST(Ramp, CheckShape) {
  const std::string tokens = "ramp,normal=-0.125:0:1,foot=8:10";
  EXPECT_EQ(check_shape(rect_ramp(tokens, 8, 10, 12, 12)), std::nullopt);
  // A vertex below the floor: x = 7 is 0.125 m under it.
  auto below = check_shape(rect_ramp(tokens, 7, 10, 12, 12));
  ASSERT_TRUE(below);
  EXPECT_NE(below->find("expected the ramp surface on or above the floor at every vertex, got -0.125 m at (7;10)"),
            std::string::npos)
      << *below;
  // Non-null height.
  Obstacle tall = rect_ramp(tokens, 8, 10, 12, 12);
  tall.segments[2].h = 0.5;
  auto h = check_shape(tall);
  ASSERT_TRUE(h);
  EXPECT_NE(h->find("expected null height on ramp segment 3, got 0.5"), std::string::npos) << *h;
  // Missing tokens.
  auto missing = check_shape(rect_ramp("ramp,concrete", 8, 10, 12, 12));
  ASSERT_TRUE(missing);
  EXPECT_NE(missing->find("normal=NX:NY:NZ"), std::string::npos);
  // A ramp is a closed polygon.
  Obstacle open = rect_ramp(tokens, 8, 10, 12, 12);
  open.segments.pop_back();
  auto o = check_shape(open);
  ASSERT_TRUE(o);
  EXPECT_NE(o->find("to close"), std::string::npos) << *o;
}

TEST(Ramp, SurfaceSurvivesAWindow) {
  const Map m = read_seed_file(kExample);
  const Obstacle& ramp = find_type(m, ShapeType::Ramp);
  auto cut = clip_obstacle(ramp, Rect{10, 0, 60, 40});
  ASSERT_TRUE(cut);
  EXPECT_EQ(check_shape(*cut, MapKind::Window), std::nullopt);
  EXPECT_TRUE(check_shape(*cut, MapKind::Whole));  // no longer closed
  EXPECT_EQ(ramp_surface(*cut), ramp_surface(ramp));
  EXPECT_EQ(ramp_surface(*cut).height_at({11, 11}), 0.375);
}

TEST(Ramp, SeedReaderRejectsBadRampWithLine) {
  const std::string text =
      "border;\n0;40;\n60;0;\n#\n"
      "obstacle;\n7;6;4;ramp,normal=-0.125:0:1;\n#\n"
      "8;10;\n12;10;\n0;1;edge;\n#\n12;10;\n12;12;\n0;1;edge;\n#\n"
      "12;12;\n8;12;\n0;1;edge;\n#\n8;12;\n8;10;\n0;1;edge;\n#\n";
  try {
    read_seed(text, "r.map");
    FAIL() << "accepted a ramp without foot";
  } catch (const MapFormatError& e) {
    EXPECT_EQ(e.line(), 6u);
    EXPECT_NE(std::string(e.what()).find("r.map:6: obstacle 7: expected 'foot=X:Y'"), std::string::npos) << e.what();
  }
}

// ---- stairs -----------------------------------------------------------------------

Segment step(Point a, Point b, double h) { return Segment{a, b, h, 1, "step", ""}; }

// Three steps going up towards +y, the closing segment at y = 1.2 oriented towards -x.
Obstacle good_stairs() {
  Obstacle o;
  o.id = 5;
  o.type = ShapeType::Stairs;
  o.semantic = "stairs";
  o.segments = {step({0, 0.3}, {4, 0.3}, 0.15), step({0, 0.6}, {4, 0.6}, 0.3), step({0, 0.9}, {4, 0.9}, 0.45),
                step({4, 1.2}, {0, 1.2}, 0)};
  return o;
}

std::string stairs_error(const Obstacle& o) {
  auto e = check_shape(o);
  return e ? *e : "";
}

TEST(Stairs, ExampleMapStairsPass) {
  const Map m = read_seed_file(kExample);
  const Obstacle& st = find_type(m, ShapeType::Stairs);
  EXPECT_EQ(check_shape(st), std::nullopt);
  ASSERT_EQ(st.segments.size(), 6u);
  // 5 steps of 0.15 m from downstairs, then the closing segment oriented the other way.
  for (size_t i = 0; i < 5; ++i) {
    EXPECT_DOUBLE_EQ(st.segments[i].h, 0.15 * double(i + 1));
    EXPECT_GT(st.segments[i].b.x, st.segments[i].a.x);
  }
  EXPECT_EQ(st.segments[5].h, 0);
  EXPECT_LT(st.segments[5].b.x, st.segments[5].a.x);
}

TEST(Stairs, SeedAppendixExamplePasses) {
  // Obstacle 26 of seed 000 appendix A (its first four segments): closing segment first.
  Obstacle o;
  o.id = 26;
  o.type = ShapeType::Stairs;
  o.semantic = "step,FIBsquare";
  o.segments = {step({34.65, 40.72}, {57.5, 40.72}, 0), step({57.5, 41.02}, {34.65, 41.02}, 2),
                step({57.5, 41.32}, {34.65, 41.32}, 1.8), step({57.5, 41.62}, {34.65, 41.62}, 1.6)};
  EXPECT_EQ(check_shape(o), std::nullopt);
}

TEST(Stairs, OrderOfSegmentsIsFree) {
  Obstacle o = good_stairs();
  std::swap(o.segments[0], o.segments[3]);
  std::swap(o.segments[1], o.segments[2]);
  EXPECT_EQ(check_shape(o), std::nullopt);
}

TEST(Stairs, InvalidStairs) {
  Obstacle none = good_stairs();
  none.segments[3].h = 0.6;
  EXPECT_NE(stairs_error(none).find("expected a closing segment with h = 0 in stairs, got none"), std::string::npos);

  Obstacle two = good_stairs();
  two.segments[0].h = 0;
  EXPECT_NE(stairs_error(two).find("expected one closing segment with h = 0 in stairs, got segments 1 and 4"),
            std::string::npos)
      << stairs_error(two);

  Obstacle alone = good_stairs();
  alone.segments = {alone.segments[3]};
  EXPECT_NE(stairs_error(alone).find("expected at least one step"), std::string::npos) << stairs_error(alone);

  Obstacle same_way = good_stairs();  // a step oriented like the closing segment
  std::swap(same_way.segments[1].a, same_way.segments[1].b);
  EXPECT_NE(stairs_error(same_way).find("expected step 2 antiparallel to the closing segment 4"), std::string::npos)
      << stairs_error(same_way);

  Obstacle oblique = good_stairs();
  oblique.segments[2].b.y = 1.0;
  EXPECT_NE(stairs_error(oblique).find("expected step 3 antiparallel"), std::string::npos) << stairs_error(oblique);

  Obstacle beyond = good_stairs();  // a step on the landing side of the closing segment
  beyond.segments[2] = step({0, 1.5}, {4, 1.5}, 0.45);
  EXPECT_NE(stairs_error(beyond).find("expected step 3 on the steps' side of the closing segment"),
            std::string::npos)
      << stairs_error(beyond);

  Obstacle closing_reversed = good_stairs();  // closing segment oriented like the steps
  std::swap(closing_reversed.segments[3].a, closing_reversed.segments[3].b);
  EXPECT_NE(stairs_error(closing_reversed).find("antiparallel"), std::string::npos) << stairs_error(closing_reversed);

  Obstacle downwards = good_stairs();  // heights falling towards the closing segment
  downwards.segments[0].h = 0.45;
  downwards.segments[2].h = 0.15;
  EXPECT_NE(stairs_error(downwards).find("expected step heights to grow towards the closing segment"),
            std::string::npos)
      << stairs_error(downwards);

  Obstacle flat = good_stairs();  // two steps of the same height
  flat.segments[1].h = 0.45;
  EXPECT_NE(stairs_error(flat).find("expected step heights to grow towards the closing segment"), std::string::npos)
      << stairs_error(flat);

  Obstacle same_place = good_stairs();
  same_place.segments[1] = step({1, 0.9}, {3, 0.9}, 0.3);
  EXPECT_NE(stairs_error(same_place).find("expected steps at distinct distances from the closing segment"),
            std::string::npos)
      << stairs_error(same_place);
}

TEST(Stairs, WindowAcceptsCutStairs) {
  // A window may cut the closing segment away: only per-segment rules apply there.
  Obstacle cut = good_stairs();
  cut.segments.pop_back();
  EXPECT_TRUE(check_shape(cut));
  EXPECT_EQ(check_shape(cut, MapKind::Window), std::nullopt);
}

TEST(Stairs, SeedReaderNamesTheObstacleLine) {
  // Break the example's stairs (swap the heights of the first and last step) and
  // read it: the error names the stairs' header line.
  std::ifstream in(kExample, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  std::string text = ss.str();
  const size_t header = text.find("6;5;6;stairs,lab;\n");
  ASSERT_NE(header, std::string::npos);
  const size_t line = 1 + std::count(text.begin(), text.begin() + header, '\n');
  const size_t first = text.find("0.15;1;step,granite;", header);
  const size_t last = text.find("0.75;1;step,granite;", header);
  ASSERT_NE(first, std::string::npos);
  ASSERT_NE(last, std::string::npos);
  text.replace(last, 4, "0.15");
  text.replace(first, 4, "0.75");
  try {
    read_seed(text, "campus.map");
    FAIL() << "accepted stairs going down towards the top";
  } catch (const MapFormatError& e) {
    EXPECT_EQ(e.line(), line);
    EXPECT_NE(e.message().find("obstacle 6: expected step heights to grow towards the closing segment"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace fleetmap
