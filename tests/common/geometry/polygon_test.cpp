// common/geometry/polygon.*: hand-computed cases (convex, concave, boundary, bow-tie, repeated
// and collinear points), points next to an edge by one ulp, and point_in_polygon /
// distance_to_polygon against references written here on random star-shaped polygons
// with integer vertices (many points fall exactly on edges and vertices).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>

#include "common/geometry/polygon.h"

namespace fleetmap {
namespace {

const Polygon kSquare = {{0, 0}, {4, 0}, {4, 4}, {0, 4}};
// A U opening upwards: the notch x in (1, 3), y in (1, 4] is outside.
const Polygon kU = {{0, 0}, {4, 0}, {4, 4}, {3, 4}, {3, 1}, {1, 1}, {1, 4}, {0, 4}};

Polygon reversed(Polygon p) {
  std::reverse(p.begin(), p.end());
  return p;
}

TEST(Polygon, ConvexInsideOutsideBoundary) {
  for (const Polygon& sq : {kSquare, reversed(kSquare)}) {
    EXPECT_TRUE(point_in_polygon({2, 2}, sq));
    EXPECT_TRUE(point_in_polygon({0, 0}, sq));    // vertex
    EXPECT_TRUE(point_in_polygon({4, 2}, sq));    // edge
    EXPECT_TRUE(point_in_polygon({2, 4}, sq));    // top edge
    EXPECT_TRUE(point_in_polygon({0, 3.5}, sq));  // left edge
    EXPECT_FALSE(point_in_polygon({4.0001, 2}, sq));
    EXPECT_FALSE(point_in_polygon({-1, 0}, sq));  // on the line of the bottom edge, left of it
    EXPECT_FALSE(point_in_polygon({5, 4}, sq));   // on the line of the top edge, right of it
    EXPECT_FALSE(point_in_polygon({2, -1e-12}, sq));
    EXPECT_EQ(polygon_area(sq), 16);
    EXPECT_EQ(polygon_bounds(sq), (Rect{0, 0, 4, 4}));
  }
}

TEST(Polygon, ConcaveNotchIsOutside) {
  for (const Polygon& u : {kU, reversed(kU)}) {
    EXPECT_FALSE(point_in_polygon({2, 2}, u));  // in the notch
    EXPECT_FALSE(point_in_polygon({2, 4}, u));  // across the notch's mouth
    EXPECT_TRUE(point_in_polygon({2, 1}, u));   // the notch's floor
    EXPECT_TRUE(point_in_polygon({3, 2.5}, u)); // its right wall
    EXPECT_TRUE(point_in_polygon({0.5, 3}, u));
    EXPECT_TRUE(point_in_polygon({3.5, 3.9}, u));
    EXPECT_TRUE(point_in_polygon({2, 0.5}, u));
    // Rays from these points along +x pass through vertices (4,4), (3,4) and (1,1), (3,1).
    EXPECT_FALSE(point_in_polygon({-1, 4}, u));
    EXPECT_TRUE(point_in_polygon({0.5, 1}, u));
    EXPECT_FALSE(point_in_polygon({-1, 1}, u));
    EXPECT_EQ(polygon_area(u), 16 - 6);
  }
}

TEST(Polygon, DistanceToPolygon) {
  EXPECT_EQ(distance_to_polygon({2, 2}, kSquare), 0);
  EXPECT_EQ(distance_to_polygon({4, 1}, kSquare), 0);
  EXPECT_DOUBLE_EQ(distance_to_polygon({7, 2}, kSquare), 3);
  EXPECT_DOUBLE_EQ(distance_to_polygon({7, 8}, kSquare), 5);  // to the corner (4,4): 3-4-5
  EXPECT_DOUBLE_EQ(distance_to_polygon({2, 3}, kU), 1);       // in the notch: to its walls and mouth
  EXPECT_DOUBLE_EQ(distance_to_polygon({2, 1.5}, kU), 0.5);   // to the notch's floor
  EXPECT_DOUBLE_EQ(distance_to_polygon({2, 4.5}, kU), std::hypot(1, 0.5));
}

TEST(Polygon, RectangleFootprint) {
  const Polygon r = rectangle_footprint({10, 5}, 2, 1, 0);
  EXPECT_EQ(r, (Polygon{{9, 4.5}, {11, 4.5}, {11, 5.5}, {9, 5.5}}));
  const Polygon t = rectangle_footprint({1, 1}, 2, 1, std::acos(-1.0) / 2);  // turned a quarter
  const Polygon expected = {{1.5, 0}, {1.5, 2}, {0.5, 2}, {0.5, 0}};
  ASSERT_EQ(t.size(), 4u);
  for (size_t i = 0; i < 4; ++i) {
    EXPECT_NEAR(t[i].x, expected[i].x, 1e-12) << i;
    EXPECT_NEAR(t[i].y, expected[i].y, 1e-12) << i;
  }
  EXPECT_NEAR(polygon_area(t), 2, 1e-12);
  EXPECT_FALSE(polygon_problem(t));
  // Counter-clockwise: the shoelace sum is positive.
  double twice = 0;
  for (size_t i = 0; i < 4; ++i) twice += t[i].x * t[(i + 1) % 4].y - t[(i + 1) % 4].x * t[i].y;
  EXPECT_GT(twice, 0);
}

TEST(Polygon, ValidRings) {
  EXPECT_FALSE(polygon_problem(kSquare));
  EXPECT_FALSE(polygon_problem(reversed(kSquare)));
  EXPECT_FALSE(polygon_problem(kU));
  EXPECT_FALSE(polygon_problem({{0, 0}, {1, 0}, {0, 1}}));
  // A collinear vertex in the middle of an edge is allowed.
  EXPECT_FALSE(polygon_problem({{0, 0}, {1, 0}, {2, 0}, {2, 2}, {0, 2}}));
  // Two vertices close together but distinct.
  EXPECT_FALSE(polygon_problem({{0, 0}, {1, 0}, {1, std::nextafter(0.0, 1.0)}, {1, 1}, {0, 1}}));
}

void expect_problem(const Polygon& ring, const std::string& words) {
  const auto p = polygon_problem(ring);
  ASSERT_TRUE(p.has_value()) << words;
  EXPECT_NE(p->find(words), std::string::npos) << *p;
}

TEST(Polygon, InvalidRings) {
  expect_problem({}, "at least 3 distinct points, got 0");
  expect_problem({{0, 0}, {1, 1}}, "at least 3 distinct points, got 2");
  expect_problem({{0, 0}, {1, 1}, {0, 0}, {1, 1}}, "at least 3 distinct points, got 2");
  expect_problem({{0, 0}, {1, 0}, {1, 0}, {0, 1}}, "vertex 2 and vertex 3 both at (1, 0)");
  expect_problem({{0, 0}, {1, 0}, {0, 1}, {0, 0}}, "vertex 4 and the first both at (0, 0)");
  expect_problem({{0, 0}, {1, 1}, {2, 2}, {3, 3}}, "non-zero area");
  expect_problem({{0, 0}, {2, 0}, {1, 0}, {1, 1}}, "spike at vertex 2");  // goes back along its edge
  // Bow-tie: edges 1 (0,0)-(2,2) and 3 (2,0)-(0,2) cross at (1,1).
  expect_problem({{0, 0}, {2, 2}, {2, 0}, {0, 2}}, "edge 1 (vertices 1-2) and edge 3 (vertices 3-4)");
  // Figure eight touching itself at a vertex (2,1) that appears twice.
  expect_problem({{0, 0}, {2, 1}, {4, 0}, {4, 2}, {2, 1}, {0, 2}}, "crossing or touching");
  // A vertex touching a non-adjacent edge.
  expect_problem({{0, 0}, {4, 0}, {4, 4}, {2, 0}, {0, 4}}, "crossing or touching");
  // Collinear overlap of non-adjacent edges.
  expect_problem({{0, 0}, {3, 0}, {3, 1}, {2, 1}, {2, 0}, {1, 0}, {1, -1}, {0, -1}}, "crossing or touching");
  expect_problem({{0, 0}, {1, 0}, {0, std::numeric_limits<double>::quiet_NaN()}}, "finite");
  expect_problem({{0, 0}, {std::numeric_limits<double>::infinity(), 0}, {0, 1}}, "vertex 2");
}

// A long diagonal edge y = x, and points one ulp off it near (0.5, 0.5): a plain
// floating-point cross product relative to (-24,-24) rounds them all onto the line.
TEST(Polygon, PointsOneUlpFromAnEdge) {
  const Polygon tri = {{-24, -24}, {24, 24}, {24, -24}};  // the half y <= x
  const double ulp = std::ldexp(1.0, -53);                // of numbers in [0.5, 1)
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 8; ++j) {
      const Point p{0.5 + i * ulp, 0.5 + j * ulp};
      EXPECT_EQ(point_in_polygon(p, tri), j <= i) << i << " " << j;
      EXPECT_EQ(point_in_polygon(p, reversed(tri)), j <= i) << i << " " << j;
    }
  // A ring with a vertex one ulp beside a non-adjacent edge is simple, on the edge it is not.
  const double y = 0.5 + ulp;
  EXPECT_FALSE(polygon_problem({{-24, -24}, {24, 24}, {0.5, y}, {-30, 0}}));
  EXPECT_TRUE(polygon_problem({{-24, -24}, {24, 24}, {24, -24}, {0.5, 0.5}, {-30, 0}}));
}

// --- random star-shaped polygons with integer vertices, exact references -------------

using I64 = int64_t;
struct IPt {
  I64 x, y;
};
I64 icross(IPt o, IPt a, IPt b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); }

// Vertices k * d for direction vectors d in strictly increasing angle, no two collinear,
// every turn between consecutive directions under pi: simple and star-shaped from (0,0).
std::vector<IPt> random_star(std::mt19937& rng) {
  std::uniform_int_distribution<int> n_dist(3, 12), c(-6, 6), k(1, 3);
  for (;;) {
    std::vector<IPt> dirs;
    const int n = n_dist(rng);
    while (static_cast<int>(dirs.size()) < n) {
      IPt d{c(rng), c(rng)};
      if (d.x == 0 && d.y == 0) continue;
      bool parallel = false;
      for (IPt e : dirs) parallel = parallel || (d.x * e.y - d.y * e.x == 0 && d.x * e.x + d.y * e.y > 0);
      if (!parallel) dirs.push_back(d);
    }
    std::sort(dirs.begin(), dirs.end(), [](IPt a, IPt b) { return std::atan2(a.y, a.x) < std::atan2(b.y, b.x); });
    bool ok = true;
    for (size_t i = 0; i < dirs.size(); ++i) ok = ok && icross({0, 0}, dirs[i], dirs[(i + 1) % dirs.size()]) > 0;
    if (!ok) continue;
    for (IPt& d : dirs) {
      const int f = k(rng);
      d = {d.x * f, d.y * f};
    }
    return dirs;
  }
}

// Inside the closed polygon: in one of the closed counter-clockwise fan triangles.
bool reference_inside(IPt p, const std::vector<IPt>& v) {
  for (size_t i = 0; i < v.size(); ++i) {
    const IPt a = v[i], b = v[(i + 1) % v.size()];
    if (icross({0, 0}, a, p) >= 0 && icross(a, b, p) >= 0 && icross(b, {0, 0}, p) >= 0) return true;
  }
  return false;
}

bool reference_on_outline(IPt p, const std::vector<IPt>& v) {
  for (size_t i = 0; i < v.size(); ++i) {
    const IPt a = v[i], b = v[(i + 1) % v.size()];
    if (icross(a, b, p) == 0 && std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) &&
        std::min(a.y, b.y) <= p.y && p.y <= std::max(a.y, b.y))
      return true;
  }
  return false;
}

double reference_distance(Point p, const Polygon& ring) {
  long double best = std::numeric_limits<long double>::infinity();
  for (size_t i = 0; i < ring.size(); ++i) {
    const Point a = ring[i], b = ring[(i + 1) % ring.size()];
    const long double ex = b.x - a.x, ey = b.y - a.y, px = p.x - a.x, py = p.y - a.y;
    long double t = (px * ex + py * ey) / (ex * ex + ey * ey);
    t = std::clamp(t, 0.0L, 1.0L);
    best = std::min(best, std::hypot(px - t * ex, py - t * ey));
  }
  return static_cast<double>(best);
}

TEST(Polygon, RandomStarPolygonsAgainstReferences) {
  std::mt19937 rng(8);
  std::uniform_int_distribution<int> coord(-40, 40);  // half-metres: x = coord / 2
  int inside = 0, boundary_hits = 0, checked = 0;
  for (int trial = 0; trial < 60; ++trial) {
    const std::vector<IPt> v = random_star(rng);
    Polygon ring;
    for (IPt q : v) ring.push_back({static_cast<double>(q.x), static_cast<double>(q.y)});
    ASSERT_FALSE(polygon_problem(ring)) << *polygon_problem(ring);
    ASSERT_FALSE(polygon_problem(reversed(ring)));
    for (int k = 0; k < 1000; ++k) {
      // Points on a half-unit grid, scaled by 2 for the integer reference.
      const IPt q2{coord(rng), coord(rng)};
      std::vector<IPt> v2;
      for (IPt a : v) v2.push_back({2 * a.x, 2 * a.y});
      const Point p{q2.x / 2.0, q2.y / 2.0};
      const bool expected = reference_inside(q2, v2);
      ASSERT_EQ(point_in_polygon(p, ring), expected) << "trial " << trial << " point " << p.x << "," << p.y;
      ASSERT_EQ(point_in_polygon(p, reversed(ring)), expected);
      const double d = distance_to_polygon(p, ring);
      if (expected) {
        ASSERT_EQ(d, 0);
        ++inside;
        if (reference_on_outline(q2, v2)) ++boundary_hits;
      } else {
        ASSERT_NEAR(d, reference_distance(p, ring), 1e-12);
        ASSERT_GT(d, 0);
      }
      ++checked;
    }
  }
  // The sample exercises both sides and the outline itself.
  EXPECT_GT(inside, checked / 20);
  EXPECT_GT(boundary_hits, 100);
}

}  // namespace
}  // namespace fleetmap
