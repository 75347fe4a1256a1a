#include "common/geometry/bounding_circle.h"

#include <algorithm>
#include <random>

namespace fleetmap {
namespace {

Circle from_two(Point a, Point b) { return {0.5 * (a + b), distance(a, b) / 2}; }

Circle from_three(Point a, Point b, Point c) {
  const Point ab = b - a, ac = c - a;
  const double d = 2 * cross(ab, ac);
  if (std::abs(d) < 1e-18) {
    // Collinear: the circle on the two farthest points.
    Circle best = from_two(a, b);
    for (const Circle& k : {from_two(a, c), from_two(b, c)})
      if (k.r > best.r) best = k;
    return best;
  }
  const double b2 = dot(ab, ab), c2 = dot(ac, ac);
  const Point centre{a.x + (ac.y * b2 - ab.y * c2) / d, a.y + (ab.x * c2 - ac.x * b2) / d};
  return {centre, std::max({distance(centre, a), distance(centre, b), distance(centre, c)})};
}

}  // namespace

Circle minimum_bounding_circle(std::vector<Point> pts) {
  if (pts.empty()) return {};
  std::mt19937 rng(12345);
  std::shuffle(pts.begin(), pts.end(), rng);
  // Iterative form of Welzl's recursion (move-to-front free, three nested loops).
  Circle c{pts[0], 0};
  for (size_t i = 1; i < pts.size(); ++i) {
    if (c.contains(pts[i])) continue;
    c = {pts[i], 0};
    for (size_t j = 0; j < i; ++j) {
      if (c.contains(pts[j])) continue;
      c = from_two(pts[i], pts[j]);
      for (size_t k = 0; k < j; ++k)
        if (!c.contains(pts[k])) c = from_three(pts[i], pts[j], pts[k]);
    }
  }
  return c;
}

}  // namespace fleetmap
