// Partial maps (SPEC 5.4, common/map/map_window.h): hand maps, then a property test on random
// maps and windows.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "common/map/map_validation.h"
#include "common/map/map_window.h"
#include "common/io/seed_format.h"

namespace fleetmap {
namespace {

Segment seg(Point a, Point b, double h = 2, std::string sem = "wall,brick", std::string note = "") {
  return Segment{a, b, h, 1, std::move(sem), std::move(note)};
}

Obstacle square(int id, double x0, double y0, double x1, double y1, double h = 3) {
  Obstacle o;
  o.id = id;
  o.type = ShapeType::ClosedPolygon;
  o.semantic = "building,b";
  o.semantic += std::to_string(id);
  o.segments = {seg({x0, y0}, {x1, y0}, h), seg({x1, y0}, {x1, y1}, h, "wall,glass", "east face"),
                seg({x1, y1}, {x0, y1}, h), seg({x0, y1}, {x0, y0}, h)};
  return o;
}

Map hand_map() {
  Map m;
  m.border = Border{0, 20, 20, 0};
  m.obstacles.push_back(square(1, 2, 2, 6, 6));
  m.obstacles.push_back(square(2, 15, 15, 18, 18));
  Obstacle bench;
  bench.id = 3;
  bench.type = ShapeType::OpenPolygon;
  bench.semantic = "bench";
  bench.segments = {seg({5, 8}, {9, 8}, 0.5, "seat,wood")};
  m.obstacles.push_back(bench);
  validate_map(m);
  m.compute_bounds();
  return m;
}

TEST(MapWindow, SquareCutByWindow) {
  const Map m = hand_map();
  const Rect r{4, 4, 10, 10};
  const Map w = clip_map(m, r);
  EXPECT_EQ(w.border, (Border{4, 10, 10, 4}));
  ASSERT_EQ(w.obstacles.size(), 2u);  // obstacle 2 lies outside the window
  const Obstacle& a = w.obstacles[0];
  EXPECT_EQ(a.id, 1);
  EXPECT_EQ(a.type, ShapeType::ClosedPolygon);
  EXPECT_EQ(a.semantic, "building,b1");
  // (2,2)-(6,2) and (2,6)-(2,2) are outside; (6,2)-(6,6) is cut to (6,4)-(6,6) and
  // (6,6)-(2,6) to (6,6)-(4,6); attributes and notes are kept.
  ASSERT_EQ(a.segments.size(), 2u);
  EXPECT_EQ(a.segments[0], seg({6, 4}, {6, 6}, 3, "wall,glass", "east face"));
  EXPECT_EQ(a.segments[1], seg({6, 6}, {4, 6}, 3));
  // The untouched bench is kept whole, after obstacle 1 (map order).
  EXPECT_EQ(w.obstacles[1], m.obstacles[2]);
  // The cut obstacle's bounding circle is the one of its remaining segments.
  EXPECT_NEAR(a.bound.c.x, 5, 1e-12);
  EXPECT_NEAR(a.bound.c.y, 5, 1e-12);
  EXPECT_NEAR(a.bound.r, std::sqrt(2.0), 1e-12);
  // A cut window is no longer a whole map, but it is a valid window.
  EXPECT_THROW(validate_map(w), std::invalid_argument);
  EXPECT_NO_THROW(validate_map(w, MapKind::Window));
  EXPECT_EQ(read_seed(write_seed(w), "<window>", MapKind::Window), w);
}

TEST(MapWindow, ObstacleOrderAndIdsKept) {
  const Map m = hand_map();
  const Map w = clip_map(m, Rect{0, 0, 20, 20});
  EXPECT_EQ(w, m);
  const Map v = clip_map(m, Rect{5, 5, 17, 17});
  ASSERT_EQ(v.obstacles.size(), 3u);
  EXPECT_EQ(v.obstacles[0].id, 1);
  EXPECT_EQ(v.obstacles[1].id, 2);
  EXPECT_EQ(v.obstacles[2].id, 3);
  // Obstacle 2's square (15..18) keeps its two sides that enter [5,17]^2, cut at 17.
  ASSERT_EQ(v.obstacles[1].segments.size(), 2u);
  // (15,15)-(18,15) -> (15,15)-(17,15); (15,18)-(15,15) -> (15,17)-(15,15).
  const auto& s2 = v.obstacles[1].segments;
  EXPECT_EQ(s2[0].a, (Point{15, 15}));
  EXPECT_DOUBLE_EQ(s2[0].b.x, 17);
  EXPECT_DOUBLE_EQ(s2[0].b.y, 15);
  EXPECT_DOUBLE_EQ(s2[1].a.x, 15);
  EXPECT_DOUBLE_EQ(s2[1].a.y, 17);
  EXPECT_EQ(s2[1].b, (Point{15, 15}));
}

TEST(MapWindow, ObstaclesOutsideDropped) {
  const Map m = hand_map();
  const Map w = clip_map(m, Rect{10, 0, 14, 20});
  EXPECT_TRUE(w.obstacles.empty());
  EXPECT_EQ(w.segment_count(), 0u);
}

TEST(MapWindow, WindowRectIsWindowIntersectBorder) {
  const Border b{0, 20, 20, 0};
  EXPECT_EQ(window_rect(b, {10, 10}, 4, 6), (Rect{8, 7, 12, 13}));
  EXPECT_EQ(window_rect(b, {18, 18}, 10, 10), (Rect{13, 13, 20, 20}));
  EXPECT_EQ(window_rect(b, {1, 19}, 10, 4), (Rect{0, 17, 6, 20}));
  EXPECT_EQ(window_rect(b, {10, 10}, 100, 100), (Rect{0, 0, 20, 20}));
  const Map w = clip_map(hand_map(), window_rect(b, {18, 18}, 10, 10));
  EXPECT_EQ(w.border, (Border{13, 20, 20, 13}));
  ASSERT_EQ(w.obstacles.size(), 1u);
  EXPECT_EQ(w.obstacles[0].id, 2);
  EXPECT_EQ(w.obstacles[0], hand_map().obstacles[1]);  // wholly inside: unchanged
}


TEST(MapWindow, WindowOutsideMapIsEmpty) {
  const Border b{0, 20, 20, 0};
  const Rect r = window_rect(b, {50, 50}, 10, 10);
  EXPECT_TRUE(r.empty());
  const Map w = clip_map(hand_map(), r);
  EXPECT_TRUE(w.obstacles.empty());
  // Touching the border along an edge only: no area, nothing.
  const Rect t = window_rect(b, {25, 10}, 10, 10);
  EXPECT_TRUE(t.empty());
  EXPECT_TRUE(clip_map(hand_map(), t).obstacles.empty());
}

// ---- property test ----------------------------------------------------------------

Map random_map(std::mt19937_64& rng, int obstacles) {
  std::uniform_real_distribution<double> u(0, 100);
  std::uniform_int_distribution<int> nseg(1, 8);
  std::uniform_real_distribution<double> step(-15, 15);
  Map m;
  m.border = Border{0, 100, 100, 0};
  for (int k = 0; k < obstacles; ++k) {
    Obstacle o;
    o.id = 10 * k + 1;
    o.type = ShapeType::OpenPolygon;
    o.semantic = "thing,";
    o.semantic += std::to_string(k);
    Point p{u(rng), u(rng)};
    const int n = nseg(rng);
    for (int i = 0; i < n; ++i) {
      Point q{std::clamp(p.x + step(rng), 0.0, 100.0), std::clamp(p.y + step(rng), 0.0, 100.0)};
      if (q == p) q.x = p.x < 50 ? p.x + 1 : p.x - 1;
      o.segments.push_back(Segment{p, q, 0.1 * i, i % 2, std::to_string(i) + "s", i == 2 ? "n" : ""});
      p = q;
    }
    m.obstacles.push_back(std::move(o));
  }
  validate_map(m);
  return m;
}

// Is c collinear with s and contained in it (within rounding)?
bool within(const Segment& c, const Segment& s) {
  const Point d = s.b - s.a;
  const double len = norm(d);
  for (Point p : {c.a, c.b}) {
    if (std::abs(cross(d, p - s.a)) / len > 1e-9) return false;
    const double t = dot(p - s.a, d) / (len * len);
    if (t < -1e-12 || t > 1 + 1e-12) return false;
  }
  // Same orientation as the original.
  return dot(c.b - c.a, d) > 0;
}

TEST(MapWindow, PropertyClippedSegmentsLieInsideAndOnOriginals) {
  std::mt19937_64 rng(314159);
  std::uniform_real_distribution<double> u(-10, 110);
  std::uniform_real_distribution<double> size(0.5, 60);
  size_t cut_segments = 0, whole_segments = 0;
  for (int iter = 0; iter < 300; ++iter) {
    const Map m = random_map(rng, 20);
    const Rect r = window_rect(m.border, {u(rng), u(rng)}, size(rng), size(rng));
    const Map w = clip_map(m, r);
    if (r.empty()) {
      EXPECT_TRUE(w.obstacles.empty());
      continue;
    }
    EXPECT_EQ(w.border, Border::from_rect(r));
    EXPECT_NO_THROW(validate_map(w, MapKind::Window));
    size_t k = 0;  // index into m.obstacles: w keeps their order
    for (const Obstacle& o : w.obstacles) {
      while (k < m.obstacles.size() && m.obstacles[k].id != o.id) ++k;
      ASSERT_LT(k, m.obstacles.size()) << "obstacle " << o.id << " not in map order";
      const Obstacle& orig = m.obstacles[k++];
      EXPECT_EQ(o.type, orig.type);
      EXPECT_EQ(o.semantic, orig.semantic);
      size_t i = 0;  // segments also keep their order
      for (const Segment& c : o.segments) {
        EXPECT_TRUE(r.contains(c.a) && r.contains(c.b))
            << "segment (" << c.a.x << "," << c.a.y << ")-(" << c.b.x << "," << c.b.y << ") outside [" << r.xmin
            << "," << r.ymin << "," << r.xmax << "," << r.ymax << "]";
        while (i < orig.segments.size() && !within(c, orig.segments[i])) ++i;
        ASSERT_LT(i, orig.segments.size()) << "cut segment of obstacle " << o.id << " is on no original segment";
        const Segment& s = orig.segments[i++];
        EXPECT_EQ(c.h, s.h);
        EXPECT_EQ(c.in_out, s.in_out);
        EXPECT_EQ(c.semantic, s.semantic);
        EXPECT_EQ(c.note, s.note);
        if (c.a == s.a && c.b == s.b) ++whole_segments;
        else ++cut_segments;
      }
    }
    // Completeness: every original segment with a point well inside r is represented.
    for (const Obstacle& o : m.obstacles)
      for (const Segment& s : o.segments) {
        bool inside = false;
        for (int t = 0; t <= 16 && !inside; ++t) {
          const Point p = s.a + (t / 16.0) * (s.b - s.a);
          inside = p.x > r.xmin + 1e-6 && p.x < r.xmax - 1e-6 && p.y > r.ymin + 1e-6 && p.y < r.ymax - 1e-6;
        }
        if (!inside) continue;
        bool found = false;
        for (const Obstacle& c : w.obstacles)
          if (c.id == o.id)
            for (const Segment& cs : c.segments) found = found || within(cs, s);
        EXPECT_TRUE(found) << "segment of obstacle " << o.id << " inside the window was dropped";
      }
  }
  EXPECT_GT(cut_segments, 300u);
  EXPECT_GT(whole_segments, 300u);
}

// A window is sent to robots as seed text (SPEC 5.4) and read back with MapKind::Window:
// its cut ends must lie inside its border exactly, not one rounding step outside.
TEST(MapWindow, PropertyWindowTextReadsBack) {
  std::mt19937_64 rng(271828);
  std::uniform_real_distribution<double> u(-10, 110);
  std::uniform_real_distribution<double> size(0.5, 60);
  int failures = 0;
  for (int iter = 0; iter < 300; ++iter) {
    const Map m = random_map(rng, 20);
    const Rect r = window_rect(m.border, {u(rng), u(rng)}, size(rng), size(rng));
    if (r.empty()) continue;
    const Map w = clip_map(m, r);
    try {
      EXPECT_EQ(read_seed(write_seed(w), "<window>", MapKind::Window), w);
    } catch (const MapFormatError& e) {
      if (++failures <= 3) ADD_FAILURE() << e.what();
    }
  }
  EXPECT_EQ(failures, 0);
}

}  // namespace
}  // namespace fleetmap
