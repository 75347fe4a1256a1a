#pragma once
// Minimum bounding circle of a point set (Welzl's algorithm, expected linear time).
// Seed 000 section 4.1: each obstacle gets one, used to cull it before ray casting.
#include <vector>

#include "common/geometry/geometry.h"

namespace fleetmap {

struct Circle {
  Point c;
  double r = 0;
  bool contains(Point p, double eps = 1e-9) const { return distance(c, p) <= r + eps; }
  friend bool operator==(const Circle&, const Circle&) = default;
};

// Exact up to floating-point rounding; deterministic (fixed shuffle seed).
Circle minimum_bounding_circle(std::vector<Point> points);

}  // namespace fleetmap
