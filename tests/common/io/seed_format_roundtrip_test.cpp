// The seed text format (seed 000 appendix A, SPEC 3) read and written without loss:
// the seeds' own examples parse to the expected model, a canonical file is rewritten
// byte for byte, loose spacing / CRLF / blank lines read to the same map, random maps
// and the real AMRL maps survive write-then-read exactly, and bounds are computed.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <climits>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "common/io/amrl_import.h"
#include "common/map/map_validation.h"
#include "common/geometry/number_format.h"
#include "common/map/ramp.h"
#include "common/io/seed_format.h"

namespace fleetmap {
namespace {

// Seed 000 appendix A (border, obstacle 1) with seed 001 Fig. 2's '%11' note on the first
// segment and its obstacle 110, as the seeds print them ("12.10", not "12.1").
const char* const kSeedExample =
    "border;\n"
    "-4;58;\n"
    "58;-4;\n"
    "#\n"
    "obstacle;\n"
    "1;1;4;column,A5;\n"
    "#\n"
    "4.53;12.10;\n"
    "7.29;12.10;\n"
    "5;1;wall,orange,brick;%11\n"
    "#\n"
    "7.29;12.10;\n"
    "7.29;13.86;\n"
    "5;1;wall,orange,brick;\n"
    "#\n"
    "7.29;13.86;\n"
    "4.53;13.86;\n"
    "5;1;wall,orange,brick;\n"
    "#\n"
    "4.53;13.86;\n"
    "4.53;12.10;\n"
    "5;1;wall,orange,brick;\n"
    "#\n"
    "obstacle;\n"
    "110;2;1;wall,A4;\n"
    "#\n"
    "-3;0;\n"
    "-4;0;\n"
    "1.2;1;wall,grey,cement;\n"
    "#\n";

// The same map as kSeedExample, written loosely by hand: CRLF, blank lines, blanks
// around fields and lines, non-canonical numbers.
const char* const kSeedExampleLoose =
    "\r\n"
    "  border;\t\r\n"
    " -4.0 ; 58 ;\r\n"
    "58.00;-4;\r\n"
    "\r\n"
    "# \r\n"
    "\t\r\n"
    "obstacle;\r\n"
    " 1 ; 1 ; 4 ; column,A5 ;\r\n"
    "#\r\n"
    "4.530 ; 12.1 ;\r\n"
    "\r\n"
    "7.29;12.100;\r\n"
    " 5.0 ; 1 ; wall,orange,brick ;%11\r\n"
    "#\r\n"
    "7.29 ;12.10 ;\r\n"
    "7.29; 13.86;\r\n"
    "5e0;1;wall,orange,brick;\r\n"
    "  #  \r\n"
    "7.29;13.86;\r\n"
    "4.53;13.860;\r\n"
    "5;1;  wall,orange,brick  ;\r\n"
    "#\r\n"
    "004.53;13.86;\r\n"
    "4.53;12.10;\r\n"
    "5.;1;wall,orange,brick;\r\n"
    "#\r\n"
    "\r\n"
    "   \r\n"
    "obstacle;\r\n"
    "110 ;2 ;1 ;wall,A4 ;\r\n"
    "#\r\n"
    "-3.0;0.0;\r\n"
    "-4;0.000;\r\n"
    "1.20;1;wall,grey,cement;\r\n"
    "#\r\n"
    "\r\n";

// A canonical file written by hand: LF, shortest round-trip numbers ("12.1", "2e+06",
// "2.5e-05", "5e-324", "0.30000000000000004"), no blank lines, every shape type,
// semantics with commas, blanks and UTF-8, free-form notes holding ';', '#' and '%'.
const char* const kCanonical =
    "border;\n"
    "-1000;2e+06;\n"
    "2e+06;-1000;\n"
    "#\n"
    "obstacle;\n"
    "1;1;4;column,A5;\n"
    "#\n"
    "4.53;12.1;\n"
    "7.29;12.1;\n"
    "5;1;wall,orange,brick;%11\n"
    "#\n"
    "7.29;12.1;\n"
    "7.29;13.86;\n"
    "5;1;wall,orange,brick;\n"
    "#\n"
    "7.29;13.86;\n"
    "4.53;13.86;\n"
    "5;1;wall,orange,brick;\n"
    "#\n"
    "4.53;13.86;\n"
    "4.53;12.1;\n"
    "5;1;wall,orange,brick;\n"
    "#\n"
    "obstacle;\n"
    "110;2;1;wall,A4;\n"
    "#\n"
    "-3;0;\n"
    "-4;0;\n"
    "1.2;1;wall,grey,cement;\n"
    "#\n"
    "obstacle;\n"
    "26;5;3;step,FIBsquare;\n"
    "#\n"
    "34.65;40.72;\n"
    "57.5;40.72;\n"
    "0;1;wall,greycement;\n"
    "#\n"
    "57.5;41.02;\n"
    "34.65;41.02;\n"
    "2;1;wall,greycement;\n"
    "#\n"
    "57.5;41.32;\n"
    "34.65;41.32;\n"
    "1.8;1;wall,greycement;%see plan; sheet #3, 100% sure\n"
    "#\n"
    "obstacle;\n"
    "40;6;4;ramp,b\xc3\xa9ton,normal=-0.125:0:1,foot=10:5;\n"
    "#\n"
    "10;5;\n"
    "20;5;\n"
    "0;0;rampe;\n"
    "#\n"
    "20;5;\n"
    "20;10;\n"
    "0;0;;\n"
    "#\n"
    "20;10;\n"
    "10;10;\n"
    "0;0;rampe;\n"
    "#\n"
    "10;10;\n"
    "10;5;\n"
    "0;0;rampe;\n"
    "#\n"
    "obstacle;\n"
    "2147483647;3;3;arbre,\xe7\x8e\xbb\xe7\x92\x83;\n"
    "#\n"
    "-1000;-1000;\n"
    "0;0.1;\n"
    "1000;1;arbre;\n"
    "#\n"
    "0;0.1;\n"
    "0.30000000000000004;-3e-07;\n"
    "5e-324;0;;\n"
    "#\n"
    "0.30000000000000004;-3e-07;\n"
    "-1000;-1000;\n"
    "0;1;arbre;%\xc3\xbc\n"
    "#\n"
    "obstacle;\n"
    "-7;4;2;;\n"
    "#\n"
    "1234567.125;-2.5e-05;\n"
    "1999999.5;1e-05;\n"
    "0.25;0;curb, low;% leading and trailing blanks \n"
    "#\n"
    "1999999.5;1e-05;\n"
    "-999.5;1999999.75;\n"
    "1e-300;1;curb, low;\n"
    "#\n";

// Each obstacle's bounding circle holds every segment end and has a positive radius
// (seed 000 section 4.1: computed once, on reading).
void expect_bounds(const Map& m, const std::string& what) {
  for (const Obstacle& o : m.obstacles) {
    EXPECT_GT(o.bound.r, 0) << what << ": obstacle " << o.id;
    const double eps = 1e-9 * std::max(1.0, std::abs(o.bound.c.x) + std::abs(o.bound.c.y) + o.bound.r);
    for (const Segment& s : o.segments)
      for (Point p : {s.a, s.b})
        EXPECT_TRUE(o.bound.contains(p, eps)) << what << ": obstacle " << o.id << " point (" << format_number(p.x)
                                              << ";" << format_number(p.y) << ") outside circle ("
                                              << format_number(o.bound.c.x) << ";" << format_number(o.bound.c.y)
                                              << ") r " << format_number(o.bound.r);
  }
}

// (a) The seeds' example parses to the model the seeds describe.
TEST(SeedRoundTrip, SeedExampleParsesToExpectedModel) {
  const Map m = read_seed(kSeedExample, "seed000.txt");
  EXPECT_EQ(m.border, (Border{-4, 58, 58, -4}));
  ASSERT_EQ(m.obstacles.size(), 2u);

  const Obstacle& column = m.obstacles[0];
  EXPECT_EQ(column.id, 1);
  EXPECT_EQ(column.type, ShapeType::ClosedPolygon);
  EXPECT_EQ(column.semantic, "column,A5");
  ASSERT_EQ(column.segments.size(), 4u);
  const Point corners[] = {{4.53, 12.10}, {7.29, 12.10}, {7.29, 13.86}, {4.53, 13.86}};
  for (size_t i = 0; i < 4; ++i) {
    const Segment& s = column.segments[i];
    EXPECT_EQ(s.a, corners[i]) << "segment " << i + 1;
    EXPECT_EQ(s.b, corners[(i + 1) % 4]) << "segment " << i + 1;
    EXPECT_EQ(s.h, 5.0);
    EXPECT_EQ(s.in_out, 1);
    EXPECT_EQ(s.semantic, "wall,orange,brick");
    EXPECT_EQ(s.note, i == 0 ? "11" : "") << "segment " << i + 1;
  }
  EXPECT_DOUBLE_EQ(column.segments[0].length(), 2.76);
  EXPECT_DOUBLE_EQ(column.segments[1].length(), 1.76);

  const Obstacle& wall = m.obstacles[1];
  EXPECT_EQ(wall.id, 110);
  EXPECT_EQ(wall.type, ShapeType::OpenPolygon);
  EXPECT_EQ(wall.semantic, "wall,A4");
  ASSERT_EQ(wall.segments.size(), 1u);
  EXPECT_EQ(wall.segments[0].a, (Point{-3, 0}));
  EXPECT_EQ(wall.segments[0].b, (Point{-4, 0}));
  EXPECT_EQ(wall.segments[0].h, 1.2);
  EXPECT_EQ(wall.segments[0].in_out, 1);
  EXPECT_EQ(wall.segments[0].semantic, "wall,grey,cement");
  EXPECT_EQ(wall.segments[0].note, "");
  EXPECT_EQ(m.segment_count(), 5u);

  // (f) The column's minimum circle is the one on its diagonal.
  EXPECT_NEAR(column.bound.c.x, (4.53 + 7.29) / 2, 1e-9);
  EXPECT_NEAR(column.bound.c.y, (12.10 + 13.86) / 2, 1e-9);
  EXPECT_NEAR(column.bound.r, std::hypot(2.76, 1.76) / 2, 1e-9);
  EXPECT_NEAR(wall.bound.c.x, -3.5, 1e-12);
  EXPECT_NEAR(wall.bound.r, 0.5, 1e-12);
  expect_bounds(m, "seed example");
}

// (a) Seed 000's stairs (obstacle 26, first three segments) read as stairs.
TEST(SeedRoundTrip, SeedStairsAndRampParse) {
  const Map m = read_seed(kCanonical);
  ASSERT_EQ(m.obstacles.size(), 6u);
  const Obstacle& stairs = m.obstacles[2];
  EXPECT_EQ(stairs.id, 26);
  EXPECT_EQ(stairs.type, ShapeType::Stairs);
  EXPECT_EQ(stairs.segments[0].h, 0);
  EXPECT_EQ(stairs.segments[1].h, 2);
  EXPECT_EQ(stairs.segments[2].h, 1.8);
  EXPECT_EQ(stairs.segments[2].note, "see plan; sheet #3, 100% sure");
  const Obstacle& ramp = m.obstacles[3];
  EXPECT_EQ(ramp.type, ShapeType::Ramp);
  EXPECT_EQ(ramp.semantic, "ramp,b\xc3\xa9ton,normal=-0.125:0:1,foot=10:5");
  const RampSurface surface = ramp_surface(ramp);
  EXPECT_EQ(surface.height_at({20, 7}), 1.25);
  EXPECT_EQ(m.obstacles[4].segments[1].h, std::numeric_limits<double>::denorm_min());
  EXPECT_EQ(m.obstacles[5].segments[0].a, (Point{1234567.125, -2.5e-05}));
  EXPECT_EQ(m.obstacles[5].segments[0].note, " leading and trailing blanks ");
  EXPECT_EQ(m.obstacles[5].segments[0].semantic, "curb, low");
  EXPECT_EQ(m.obstacles[5].semantic, "");
  expect_bounds(m, "canonical");
}

// (b) A canonical file is rewritten byte for byte.
TEST(SeedRoundTrip, CanonicalTextRewrittenByteForByte) {
  EXPECT_EQ(write_seed(read_seed(kCanonical)), kCanonical);
}

// (c) Loose layout reads to the same map as the canonical layout.
TEST(SeedRoundTrip, CrlfBlankLinesAndSpacesReadToEqualMap) {
  const Map loose = read_seed(kSeedExampleLoose, "loose.txt");
  const Map strict = read_seed(kSeedExample, "strict.txt");
  EXPECT_EQ(loose, strict);
  EXPECT_EQ(loose.obstacles.at(0).segments.at(0).note, "11");  // no '\r' in the note
  EXPECT_EQ(write_seed(loose), write_seed(strict));
}

// (c) The whole canonical file, loosened line by line: CRLF, a blank line between every
// two lines, blanks around every field (notes untouched).
TEST(SeedRoundTrip, LoosenedCanonicalReadsToEqualMap) {
  const std::string canonical = kCanonical;
  std::string loose;
  const char* blanks[] = {"", "  ", "\t", " \t "};
  size_t n = 0;
  for (size_t pos = 0; pos < canonical.size();) {
    const size_t end = canonical.find('\n', pos);
    std::string line = canonical.substr(pos, end - pos);
    pos = end + 1;
    const size_t pct = line.find('%');
    std::string content = line.substr(0, pct);
    const std::string note = pct == std::string::npos ? "" : line.substr(pct);
    if (content == "border;" || content == "obstacle;" || content == "#") {
      content = " " + content + "\t";
    } else {
      std::string spaced = " ";
      for (char ch : content) spaced += ch == ';' ? std::string(" ; ") : std::string(1, ch);
      content = spaced;
    }
    loose += blanks[n++ % 4];
    loose += "\r\n";
    loose += content + note + "\r\n";
  }
  const Map expected = read_seed(kCanonical);
  const Map m = read_seed(loose, "loose.txt");
  EXPECT_EQ(m, expected);
  EXPECT_EQ(write_seed(m), kCanonical);
}

// --- (d) random maps ---------------------------------------------------------------------

class RandomMaps {
 public:
  explicit RandomMaps(unsigned seed) : rng_(seed) {}

  Map make() {
    Map m;
    // Border: from millimetre-sized to the largest accepted, centred off the origin.
    const int scale = pick(5);
    if (scale == 4) {
      m.border = {-kMaxCoordinate, kMaxCoordinate, kMaxCoordinate, -kMaxCoordinate};
    } else {
      const double s = std::array{1e-3, 1.0, 1e3, 1e6}[static_cast<size_t>(scale)];
      const double cx = uniform(-s, s), cy = uniform(-s, s);
      const double w = s * uniform(0.5, 2), h = s * uniform(0.5, 2);
      m.border = {cx - w, cy + h, cx + w, cy - h};
    }
    const Rect r = m.border.rect();
    std::set<int> ids;
    const int count = 1 + pick(12);
    for (int k = 0; k < count; ++k) {
      Obstacle o;
      do {
        o.id = pick(3) == 0 ? std::uniform_int_distribution<int>(-2147483647, 2147483647)(rng_)
                            : std::uniform_int_distribution<int>(-50, 1000)(rng_);
      } while (!ids.insert(o.id).second);
      o.type = static_cast<ShapeType>(1 + pick(6));
      o.semantic = semantic();
      switch (o.type) {
        case ShapeType::Stairs: stairs(o, r); break;
        case ShapeType::Ramp: ramp(o, r); break;
        default: chain(o, r, is_closed(o.type)); break;
      }
      m.obstacles.push_back(std::move(o));
    }
    return m;
  }

 private:
  int pick(int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng_); }
  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng_); }
  Point inside(const Rect& r) { return {uniform(r.xmin, r.xmax), uniform(r.ymin, r.ymax)}; }

  double height() {
    switch (pick(6)) {
      case 0: return 0;
      case 1: return uniform(0, 1) * 1e-300;
      case 2: return std::numeric_limits<double>::denorm_min() * (1 + pick(1000));
      case 3: return kMaxHeight;
      default: return uniform(0, kMaxHeight);
    }
  }
  std::string semantic() {
    static const char* const kWords[] = {
        "wall", "wall,orange,brick", "", "column,A5", "mur,b\xc3\xa9ton,gris", "\xe7\x8e\xbb\xe7\x92\x83,window",
        "door 3,open", "kerb=low,x:y", "step,FIBsquare"};
    return kWords[pick(9)];
  }
  std::string note() {
    static const char* const kNotes[] = {"", "", "", "11", "see plan; sheet #3", "100% sure", " leading",
                                         "trailing ", "\xc3\xbc"};
    return kNotes[pick(9)];
  }
  Segment segment(Point a, Point b, double h) {
    Segment s;
    s.a = a;
    s.b = b;
    s.h = h;
    s.in_out = pick(2);
    s.semantic = semantic();
    s.note = note();
    return s;
  }

  // ST 1..4: a chain of random points, back to its start when closed.
  void chain(Obstacle& o, const Rect& r, bool closed) {
    const int n = closed ? 3 + pick(6) : 1 + pick(6);
    std::vector<Point> pts;
    for (int i = 0; i < (closed ? n : n + 1); ++i) pts.push_back(inside(r));
    if (closed) pts.push_back(pts.front());
    for (int i = 0; i < n; ++i) o.segments.push_back(segment(pts[i], pts[i + 1], height()));
  }

  // ST 5, seed 000 Fig. 1: a closing segment (h = 0) from c to c + L u, steps oriented
  // the other way at growing distances on its left, lower as they go away from it.
  void stairs(Obstacle& o, const Rect& r) {
    const double m = std::min(r.xmax - r.xmin, r.ymax - r.ymin);
    const Point c{(r.xmin + r.xmax) / 2, (r.ymin + r.ymax) / 2};
    const double angle = uniform(0, 2 * std::numbers::pi);
    const Point u{std::cos(angle), std::sin(angle)};
    const Point in{-u.y, u.x};
    const double len = m * uniform(0.05, 0.15);
    const int steps = 1 + pick(5);
    const double top = uniform(0.1, 5);
    std::vector<Segment> segs;
    segs.push_back(segment(c, c + len * u, 0));
    for (int k = 1; k <= steps; ++k) {
      const double d = m * 0.05 * k;
      const double h = top * (steps + 1 - k) / steps;
      segs.push_back(segment(c + len * u + d * in, c + d * in, h));
    }
    std::shuffle(segs.begin(), segs.end(), rng_);
    o.segments = std::move(segs);
  }

  // ST 6: a closed chain of null height, its surface in the semantic (common/map/ramp.h),
  // with the foot at the lowest vertex so that no vertex is below the floor.
  void ramp(Obstacle& o, const Rect& r) {
    const int n = 3 + pick(4);
    std::vector<Point> pts;
    for (int i = 0; i < n; ++i) pts.push_back(inside(r));
    const double nx = uniform(-0.3, 0.3), ny = uniform(-0.3, 0.3), nz = uniform(0.5, 2);
    const Point g{-nx / nz, -ny / nz};
    const Point foot = *std::min_element(pts.begin(), pts.end(), [&](Point a, Point b) { return dot(g, a) < dot(g, b); });
    pts.push_back(pts.front());
    for (int i = 0; i < n; ++i) o.segments.push_back(segment(pts[i], pts[i + 1], 0));
    o.semantic = "ramp," + semantic() + (pick(2) ? "," : ",x,") + ramp_tokens(nx, ny, nz, foot);
  }

  std::mt19937 rng_;
};

TEST(SeedRoundTrip, RandomMapsSurviveWriteThenReadExactly) {
  RandomMaps gen(20240611u);
  size_t segments = 0;
  std::set<ShapeType> types;
  for (int k = 0; k < 50; ++k) {
    const Map m = gen.make();
    ASSERT_NO_THROW(validate_map(m)) << "generator made an invalid map #" << k;
    for (const Obstacle& o : m.obstacles) types.insert(o.type);
    segments += m.segment_count();
    const std::string text = write_seed(m);
    Map back;
    try {
      back = read_seed(text, "random" + std::to_string(k) + ".txt");
    } catch (const MapFormatError& e) {
      ADD_FAILURE() << "map #" << k << ": " << e.what();
      continue;
    }
    EXPECT_TRUE(back == m) << "map #" << k << ":\n" << text;
    EXPECT_EQ(write_seed(back), text) << "map #" << k;
    expect_bounds(back, "random map #" + std::to_string(k));
  }
  EXPECT_EQ(types.size(), 6u);  // every shape type was generated
  EXPECT_GT(segments, 500u);
}

// Numbers at the edges of what a double holds are written so that they read back the same.
TEST(SeedRoundTrip, ExtremeNumbersSurvive) {
  const double values[] = {kMaxCoordinate, -kMaxCoordinate, std::numeric_limits<double>::denorm_min(),
                           -std::numeric_limits<double>::denorm_min(), std::numeric_limits<double>::min(),
                           0.1 + 0.2, 1.0 / 3, -2.0 / 3 * 1e6, std::nextafter(1.0, 2.0), 123456.78901234567};
  Map m;
  m.border = {-kMaxCoordinate, kMaxCoordinate, kMaxCoordinate, -kMaxCoordinate};
  int id = 1;
  for (double v : values) {
    Obstacle o;
    o.id = id++;
    o.type = ShapeType::OpenPolygon;
    o.segments.push_back({{v, 0}, {0, v == 0 ? 1 : -v}, std::fabs(std::fmod(v, kMaxHeight)), 0, "x", ""});
    m.obstacles.push_back(o);
  }
  ASSERT_NO_THROW(validate_map(m));
  const std::string text = write_seed(m);
  const Map back = read_seed(text);
  EXPECT_TRUE(back == m) << text;
  EXPECT_EQ(write_seed(back), text);
}

// A map that passes validate_map must survive write-then-read: the writer has no other
// way to refuse it. KNOWN BUGS, see the messages.
TEST(SeedRoundTrip, ValidatedMapWithBlankEdgedSemanticsSurvives) {
  Map m;
  m.border = {-10, 10, 10, -10};
  Obstacle o;
  o.id = 1;
  o.type = ShapeType::OpenPolygon;
  o.semantic = " wall ";
  o.segments.push_back({{0, 0}, {1, 1}, 2, 0, "  brick", ""});
  m.obstacles.push_back(o);
  bool valid = true;
  try {
    validate_map(m);
  } catch (const std::invalid_argument&) {
    valid = false;  // refusing such semantics is one acceptable fix
  }
  if (valid) {
    const Map back = read_seed(write_seed(m));
    EXPECT_EQ(back.obstacles.at(0).semantic, " wall ");
    EXPECT_EQ(back.obstacles.at(0).segments.at(0).semantic, "  brick");
    EXPECT_TRUE(back == m)
        << "KNOWN BUG: check_text accepts semantic strings with leading/trailing blanks, "
           "write_seed writes them, and read_seed trims them: the map changes on the way";
  }
}

TEST(SeedRoundTrip, ValidatedMapWithSmallestIntIdSurvives) {
  Map m;
  m.border = {-10, 10, 10, -10};
  Obstacle o;
  o.id = INT_MIN;
  o.type = ShapeType::OpenPolygon;
  o.semantic = "wall";
  o.segments.push_back({{0, 0}, {1, 1}, 2, 0, "brick", ""});
  m.obstacles.push_back(o);
  bool valid = true;
  try {
    validate_map(m);
  } catch (const std::invalid_argument&) {
    valid = false;
  }
  if (valid) {
    try {
      EXPECT_EQ(read_seed(write_seed(m)), m);
    } catch (const MapFormatError& e) {
      ADD_FAILURE() << "KNOWN BUG: validate_map accepts obstacle id INT_MIN, write_seed writes it, read_seed "
                       "refuses ids below -2147483647: "
                    << e.what();
    }
  }
}

// --- (e) the real AMRL maps ------------------------------------------------------------------

class SeedRoundTripAmrl : public ::testing::TestWithParam<const char*> {};

TEST_P(SeedRoundTripAmrl, ImportedMapSurvivesSeedText) {
  const std::string path = std::string(FLEETMAP_REAL_MAPS) + "/" + GetParam();
  const Map m = read_amrl_file(path, AmrlOptions{});
  ASSERT_GT(m.segment_count(), 1000u);
  const std::string text = write_seed(m);
  const Map back = read_seed(text, path + ".seed.txt");
  EXPECT_EQ(back.border, m.border);
  ASSERT_EQ(back.obstacles.size(), m.obstacles.size());
  EXPECT_EQ(back.segment_count(), m.segment_count());
  EXPECT_TRUE(back == m);  // (gtest would print both maps on failure: too long)
  EXPECT_TRUE(write_seed(back) == text);
  expect_bounds(back, GetParam());
  // Bounds are derived from the segments alone: the same on both sides.
  for (size_t i = 0; i < m.obstacles.size(); ++i) EXPECT_EQ(back.obstacles[i].bound, m.obstacles[i].bound);
}

INSTANTIATE_TEST_SUITE_P(SeedFormat, SeedRoundTripAmrl,
                         ::testing::Values("GDC1.vectormap.txt", "UT_Campus.vectormap.txt"),
                         [](const ::testing::TestParamInfo<const char*>& info) {
                           std::string n = info.param;
                           return n.substr(0, n.find('.'));
                         });

}  // namespace
}  // namespace fleetmap
