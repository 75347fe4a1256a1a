// The AMRL vector-map importer (common/io/amrl_import.h) on the real maps (FLEETMAP_REAL_MAPS) and
// on hand-written malformed input.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "common/io/amrl_import.h"
#include "common/map/map_validation.h"
#include "common/io/seed_format.h"

namespace fleetmap {
namespace {

const std::string kMaps = FLEETMAP_REAL_MAPS;

struct Line4 {
  double x1, y1, x2, y2;
};

// The file parsed independently of the importer: every non-blank line, with sscanf.
struct Parsed {
  std::vector<Line4> kept;  // non-zero length, in file order
  size_t lines = 0, zero = 0;
  size_t chains = 0, closed = 0;
  double xmin = std::numeric_limits<double>::infinity(), ymin = xmin, xmax = -xmin, ymax = -xmin;
};

Parsed parse_independently(const std::string& path) {
  Parsed p;
  std::FILE* f = std::fopen(path.c_str(), "r");
  EXPECT_NE(f, nullptr) << path;
  if (!f) return p;
  char buf[512];
  while (std::fgets(buf, sizeof buf, f)) {
    Line4 l;
    char tail;
    const int n = std::sscanf(buf, " %lf , %lf , %lf , %lf %c", &l.x1, &l.y1, &l.x2, &l.y2, &tail);
    if (n == EOF) continue;  // blank
    EXPECT_EQ(n, 4) << buf;
    ++p.lines;
    if (l.x1 == l.x2 && l.y1 == l.y2) {
      ++p.zero;
      continue;
    }
    p.kept.push_back(l);
    p.xmin = std::min({p.xmin, l.x1, l.x2});
    p.xmax = std::max({p.xmax, l.x1, l.x2});
    p.ymin = std::min({p.ymin, l.y1, l.y2});
    p.ymax = std::max({p.ymax, l.y1, l.y2});
  }
  std::fclose(f);
  // Chains: a kept line continues the previous kept one when it starts where that ends.
  size_t start = 0;
  for (size_t i = 0; i <= p.kept.size(); ++i) {
    const bool breaks = i == p.kept.size() || i == 0 ||
                        !(p.kept[i].x1 == p.kept[i - 1].x2 && p.kept[i].y1 == p.kept[i - 1].y2);
    if (!breaks || i == 0) continue;
    ++p.chains;
    const size_t n = i - start;
    if (n >= 3 && p.kept[i - 1].x2 == p.kept[start].x1 && p.kept[i - 1].y2 == p.kept[start].y1) ++p.closed;
    start = i;
  }
  return p;
}

void check_real_map(const std::string& name, size_t want_segments, size_t want_zero) {
  SCOPED_TRACE(name);
  const std::string path = kMaps + "/" + name;
  const Parsed p = parse_independently(path);
  EXPECT_EQ(p.kept.size(), want_segments);
  EXPECT_EQ(p.zero, want_zero);

  AmrlReport rep;
  const Map m = read_amrl_file(path, AmrlOptions{}, &rep);
  EXPECT_EQ(rep.segments, want_segments);
  EXPECT_EQ(rep.zero_length_skipped, want_zero);
  EXPECT_EQ(rep.lines, p.lines);
  EXPECT_EQ(m.segment_count(), want_segments);
  EXPECT_EQ(rep.obstacles, m.obstacles.size());
  EXPECT_EQ(rep.obstacles, p.chains);
  EXPECT_EQ(rep.closed, p.closed);
  EXPECT_NO_THROW(validate_map(m));

  // The segments are the file's non-zero lines, in order, with the default options.
  size_t k = 0, closed = 0;
  int id = 1;
  for (const Obstacle& o : m.obstacles) {
    EXPECT_EQ(o.id, id++);
    EXPECT_EQ(o.semantic, "wall");
    ASSERT_FALSE(o.segments.empty());
    for (size_t i = 0; i < o.segments.size(); ++i, ++k) {
      const Segment& s = o.segments[i];
      ASSERT_LT(k, p.kept.size());
      EXPECT_EQ(s.a, (Point{p.kept[k].x1, p.kept[k].y1}));
      EXPECT_EQ(s.b, (Point{p.kept[k].x2, p.kept[k].y2}));
      EXPECT_EQ(s.h, 2.0);
      EXPECT_EQ(s.in_out, 0);
      EXPECT_EQ(s.semantic, "wall");
      EXPECT_EQ(s.note, "");
      if (i > 0) {
        EXPECT_EQ(s.a, o.segments[i - 1].b) << "obstacle " << o.id << " is not one chain";
      }
    }
    const bool closes = o.segments.size() >= 3 && o.segments.back().b == o.segments.front().a;
    EXPECT_EQ(o.type, closes ? ShapeType::ClosedPolygon : ShapeType::OpenPolygon) << "obstacle " << o.id;
    closed += closes;
  }
  EXPECT_EQ(k, want_segments);
  EXPECT_EQ(closed, rep.closed);
  // Consecutive obstacles are really separate chains.
  for (size_t i = 1; i < m.obstacles.size(); ++i)
    EXPECT_NE(m.obstacles[i].segments.front().a, m.obstacles[i - 1].segments.back().b);

  // Border: the bounding box grown by the 1 m margin.
  EXPECT_EQ(m.border, (Border{p.xmin - 1, p.ymax + 1, p.xmax + 1, p.ymin - 1}));
  const Rect inner{m.border.mx1 + 1 - 1e-9, m.border.my4 + 1 - 1e-9, m.border.mx4 - 1 + 1e-9, m.border.my1 - 1 + 1e-9};
  for (const Obstacle& o : m.obstacles)
    for (const Segment& s : o.segments) EXPECT_TRUE(inner.contains(s.a) && inner.contains(s.b));

  // The imported map survives the seed format.
  EXPECT_EQ(read_seed(write_seed(m)), m);
}

TEST(AmrlImport, Gdc1) { check_real_map("GDC1.vectormap.txt", 1289, 0); }

TEST(AmrlImport, UtCampus) { check_real_map("UT_Campus.vectormap.txt", 1533, 51); }

TEST(AmrlImport, OptionsLandOnEverySegment) {
  AmrlOptions opt;
  opt.height = 3.5;
  opt.in_out = 1;
  opt.semantic = "wall,amrl,ut";
  opt.margin = 2.5;
  opt.first_id = 100;
  AmrlReport rep;
  const Map m = read_amrl_file(kMaps + "/UT_Campus.vectormap.txt", opt, &rep);
  ASSERT_FALSE(m.obstacles.empty());
  int id = 100;
  for (const Obstacle& o : m.obstacles) {
    EXPECT_EQ(o.id, id++);
    EXPECT_EQ(o.semantic, "wall,amrl,ut");
    for (const Segment& s : o.segments) {
      EXPECT_EQ(s.h, 3.5);
      EXPECT_EQ(s.in_out, 1);
      EXPECT_EQ(s.semantic, "wall,amrl,ut");
    }
  }
  const Parsed p = parse_independently(kMaps + "/UT_Campus.vectormap.txt");
  EXPECT_EQ(m.border, (Border{p.xmin - 2.5, p.ymax + 2.5, p.xmax + 2.5, p.ymin - 2.5}));
}

TEST(AmrlImport, SmallChains) {
  // A square drawn in order (closed), then an L (open), then a back-and-forth pair
  // (open: fewer than 3 segments); blank and CRLF lines; a zero-length line inside the
  // L does not break it.
  const std::string text =
      "0, 0, 1, 0\r\n1, 0, 1, 1\n\n1, 1, 0, 1\n  0,1,0,0  \n"
      "5, 5, 6, 5\n6, 5, 6, 5\n6, 5, 6, 7\n"
      "9, 9, 9.5, 9\n9.5, 9, 9, 9\n";
  AmrlReport rep;
  const Map m = read_amrl(text, AmrlOptions{}, &rep, "small.txt");
  EXPECT_EQ(rep.lines, 9u);
  EXPECT_EQ(rep.segments, 8u);
  EXPECT_EQ(rep.zero_length_skipped, 1u);
  EXPECT_EQ(rep.obstacles, 3u);
  EXPECT_EQ(rep.closed, 1u);
  ASSERT_EQ(m.obstacles.size(), 3u);
  EXPECT_EQ(m.obstacles[0].type, ShapeType::ClosedPolygon);
  EXPECT_EQ(m.obstacles[0].segments.size(), 4u);
  EXPECT_EQ(m.obstacles[1].type, ShapeType::OpenPolygon);
  EXPECT_EQ(m.obstacles[1].segments.size(), 2u);
  EXPECT_EQ(m.obstacles[2].type, ShapeType::OpenPolygon);
  EXPECT_EQ(m.obstacles[2].segments.size(), 2u);
  EXPECT_EQ(m.border, (Border{-1, 10, 10.5, -1}));
}

// The MapFormatError of read_amrl, or a failure.
MapFormatError amrl_error(const std::string& text) {
  try {
    read_amrl(text, AmrlOptions{}, nullptr, "bad.txt");
  } catch (const MapFormatError& e) {
    return e;
  }
  ADD_FAILURE() << "accepted: " << text;
  return MapFormatError("", 0, "");
}

TEST(AmrlImport, MalformedLinesNameTheLine) {
  const std::string good = "0, 0, 1, 0\n\n1, 0, 1, 1\n";  // lines 1-3
  struct Case {
    std::string line, want;
  } cases[] = {
      {"1, 2, 3", "expected 4 comma-separated numbers 'x1, y1, x2, y2', got '1, 2, 3'"},
      {"1, 2, 3, 4, 5", "expected 4 comma-separated numbers"},
      {"1, 2, 3, 4,", "expected 4 comma-separated numbers"},
      {"wall", "expected 4 comma-separated numbers 'x1, y1, x2, y2', got 'wall'"},
      {"wall, 2, 3, 4", "expected a finite number for field 1 of 'x1, y1, x2, y2', got 'wall'"},
      {"1, nan, 3, 4", "expected a finite number for field 2 of 'x1, y1, x2, y2', got 'nan'"},
      {"1, 2, inf, 4", "expected a finite number for field 3"},
      {"1, 2, 3, 1e8", "expected a finite number for field 4"},
      {"1, , 3, 4", "expected a finite number for field 2"},
      {"1; 2; 3; 4", "expected 4 comma-separated numbers"},
      {"1 2, 3, 4, 5", "expected a finite number for field 1"},
  };
  for (const Case& c : cases) {
    const MapFormatError e = amrl_error(good + c.line + "\n0, 0, 5, 5\n");
    EXPECT_EQ(e.line(), 4u) << c.line;
    EXPECT_EQ(e.file(), "bad.txt");
    EXPECT_NE(e.message().find(c.want), std::string::npos) << c.line << " -> " << e.what();
    EXPECT_EQ(std::string(e.what()).rfind("bad.txt:4: expected ", 0), 0u) << e.what();
  }
  // On the first line, and on a last line without newline.
  EXPECT_EQ(amrl_error("1, 2, 3\n").line(), 1u);
  EXPECT_EQ(amrl_error(good + "1, 2, 3").line(), 4u);
}

TEST(AmrlImport, NothingToImport) {
  for (const std::string text : {"", "\n\n", "1, 1, 1, 1\n2, 2, 2, 2\n"}) {
    const MapFormatError e = amrl_error(text);
    EXPECT_NE(e.message().find("expected at least one segment of non-zero length, got none"), std::string::npos)
        << e.what();
  }
}

TEST(AmrlImport, BadSemanticOption) {
  AmrlOptions opt;
  opt.semantic = "wall;brick";
  EXPECT_THROW(read_amrl("0, 0, 1, 0\n", opt), MapFormatError);
}

}  // namespace
}  // namespace fleetmap
