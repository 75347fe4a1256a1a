// minimum_bounding_circle (common/geometry/bounding_circle.h): hand cases, then a comparison with
// an O(n^4) brute force over every circle through two or three of the points.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "common/geometry/bounding_circle.h"

namespace fleetmap {
namespace {

void expect_circle(const Circle& c, Point centre, double r, double tol = 1e-12) {
  EXPECT_NEAR(c.c.x, centre.x, tol);
  EXPECT_NEAR(c.c.y, centre.y, tol);
  EXPECT_NEAR(c.r, r, tol);
}

TEST(BoundingCircle, EmptyAndSinglePoint) {
  EXPECT_EQ(minimum_bounding_circle({}).r, 0);
  expect_circle(minimum_bounding_circle({{3, -4}}), {3, -4}, 0);
}

TEST(BoundingCircle, TwoPoints) {
  expect_circle(minimum_bounding_circle({{0, 0}, {2, 0}}), {1, 0}, 1);
  expect_circle(minimum_bounding_circle({{-1, -1}, {2, 3}}), {0.5, 1}, 2.5);  // 3-4-5
}

TEST(BoundingCircle, EquilateralTriangle) {
  // Side 2: circumcentre (1, sqrt(3)/3), circumradius 2/sqrt(3).
  const double s3 = std::sqrt(3.0);
  expect_circle(minimum_bounding_circle({{0, 0}, {2, 0}, {1, s3}}), {1, s3 / 3}, 2 / s3);
}

TEST(BoundingCircle, RightTriangleUsesHypotenuse) {
  expect_circle(minimum_bounding_circle({{0, 0}, {4, 0}, {0, 3}}), {2, 1.5}, 2.5);
}

TEST(BoundingCircle, ObtuseTriangleUsesLongSide) {
  // The circumcircle of (0,0),(10,0),(5,1) has radius 13; the smallest circle is the
  // one on the long side: centre (5,0), radius 5.
  for (auto pts : {std::vector<Point>{{0, 0}, {10, 0}, {5, 1}}, std::vector<Point>{{5, 1}, {0, 0}, {10, 0}},
                   std::vector<Point>{{10, 0}, {5, 1}, {0, 0}}})
    expect_circle(minimum_bounding_circle(pts), {5, 0}, 5);
}

TEST(BoundingCircle, CollinearPoints) {
  expect_circle(minimum_bounding_circle({{0, 0}, {1, 1}, {3, 3}, {2, 2}}), {1.5, 1.5}, 1.5 * std::sqrt(2.0));
  expect_circle(minimum_bounding_circle({{0, 5}, {0, -1}, {0, 2}, {0, 0}, {0, 4}}), {0, 2}, 3);
}

TEST(BoundingCircle, Duplicates) {
  expect_circle(minimum_bounding_circle({{1, 1}, {1, 1}, {3, 1}, {1, 1}, {3, 1}, {3, 1}, {1, 1}}), {2, 1}, 1);
  expect_circle(minimum_bounding_circle({{7, 7}, {7, 7}, {7, 7}}), {7, 7}, 0);
}

TEST(BoundingCircle, SquareAndInteriorPoints) {
  expect_circle(minimum_bounding_circle({{0, 0}, {2, 0}, {2, 2}, {0, 2}, {1, 1}, {0.5, 1.5}}), {1, 1},
                std::sqrt(2.0));
}

// ---- brute force ------------------------------------------------------------------

// slack: absolute rounding allowance, a few ulps of the largest coordinate.
bool covers(Point c, double r, const std::vector<Point>& pts, double slack) {
  for (Point p : pts)
    if (distance(c, p) > r * (1 + 1e-12) + slack) return false;
  return true;
}

double max_abs(const std::vector<Point>& pts) {
  double m = 0;
  for (Point p : pts) m = std::max({m, std::abs(p.x), std::abs(p.y)});
  return m;
}

// Smallest circle among those on the diameter of two points or through three points
// that contains every point: the minimum enclosing circle is one of them.
double brute_force_radius(const std::vector<Point>& pts) {
  if (pts.size() == 1) return 0;
  double best = std::numeric_limits<double>::infinity();
  const size_t n = pts.size();
  const double slack = 1e-12 + 8 * std::numeric_limits<double>::epsilon() * max_abs(pts);
  for (size_t i = 0; i < n; ++i)
    for (size_t j = i + 1; j < n; ++j) {
      const Point c = 0.5 * (pts[i] + pts[j]);
      const double r = distance(pts[i], pts[j]) / 2;
      if (r < best && covers(c, r, pts, slack)) best = r;
      for (size_t k = j + 1; k < n; ++k) {
        // Circumcentre from the perpendicular bisectors (in coordinates relative to the
        // first point, so that a far offset costs no precision), solved by Cramer's rule.
        const Point a = pts[i], b = pts[j], q = pts[k];
        const Point u = b - a, v = q - a;
        const double a1 = 2 * u.x, b1 = 2 * u.y, c1 = dot(u, u);
        const double a2 = 2 * v.x, b2 = 2 * v.y, c2 = dot(v, v);
        const double det = a1 * b2 - a2 * b1;
        if (std::abs(det) <= 1e-12 * (dot(u, u) + dot(v, v))) continue;  // collinear
        const Point cc = a + Point{(c1 * b2 - c2 * b1) / det, (a1 * c2 - a2 * c1) / det};
        const double rr = std::max({distance(cc, a), distance(cc, b), distance(cc, q)});
        if (rr < best && covers(cc, rr, pts, slack)) best = rr;
      }
    }
  return best;
}

TEST(BoundingCircle, RandomSetsAgainstBruteForce) {
  std::mt19937_64 rng(4242);
  std::uniform_int_distribution<int> count(1, 14);
  std::uniform_real_distribution<double> u(-50, 50);
  std::uniform_real_distribution<double> scale_exp(-3, 3);
  for (int set = 0; set < 200; ++set) {
    const int n = count(rng);
    const double scale = std::pow(10.0, scale_exp(rng));
    const Point offset{u(rng) * 10, u(rng) * 10};
    std::vector<Point> pts;
    for (int i = 0; i < n; ++i) pts.push_back(offset + scale * Point{u(rng), u(rng)});
    if (set % 5 == 0 && n > 2) pts.push_back(pts[n / 2]);  // a duplicate now and then
    const Circle c = minimum_bounding_circle(pts);
    const double want = brute_force_radius(pts);
    EXPECT_NEAR(c.r, want, 1e-9 * std::max(want, 1e-300)) << "set " << set << " of " << pts.size() << " points";
    for (Point p : pts) EXPECT_LE(distance(c.c, p), c.r * (1 + 1e-9)) << "set " << set;
  }
}

// Coordinates far from the origin (up to 5e6 m, within kMaxCoordinate): rounding of
// the coordinates themselves (~1e-9 m) is all the error allowed.
TEST(BoundingCircle, RandomSetsFarFromOrigin) {
  std::mt19937_64 rng(1717);
  std::uniform_int_distribution<int> count(1, 10);
  std::uniform_real_distribution<double> u(-50, 50);
  for (int set = 0; set < 200; ++set) {
    const int n = count(rng);
    const Point offset{u(rng) * 1e5, u(rng) * 1e5};
    std::vector<Point> pts;
    for (int i = 0; i < n; ++i) pts.push_back(offset + Point{u(rng), u(rng)});
    const double slack = 16 * std::numeric_limits<double>::epsilon() * max_abs(pts);
    const Circle c = minimum_bounding_circle(pts);
    const double want = brute_force_radius(pts);
    EXPECT_NEAR(c.r, want, 1e-9 * want + slack) << "set " << set << " of " << pts.size() << " points";
    for (Point p : pts) EXPECT_LE(distance(c.c, p), c.r + slack) << "set " << set;
  }
}

TEST(BoundingCircle, RandomCollinearSets) {
  // Points on a line, not on a grid: the circle is on the two extreme points.
  std::mt19937_64 rng(99);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int set = 0; set < 200; ++set) {
    const Point base{u(rng) * 100, u(rng) * 100}, dir{u(rng), u(rng)};
    std::vector<Point> pts;
    double tmin = 1e300, tmax = -1e300;
    for (int i = 0; i < 12; ++i) {
      const double t = u(rng) * 10;
      tmin = std::min(tmin, t);
      tmax = std::max(tmax, t);
      pts.push_back(base + t * dir);
    }
    const double want = (tmax - tmin) * norm(dir) / 2;
    const Circle c = minimum_bounding_circle(pts);
    EXPECT_NEAR(c.r, want, 1e-9 * want) << "set " << set;
    for (Point p : pts) EXPECT_LE(distance(c.c, p), c.r * (1 + 1e-9)) << "set " << set;
  }
}

}  // namespace
}  // namespace fleetmap
