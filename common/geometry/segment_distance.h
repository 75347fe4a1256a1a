#pragma once
// Exact Euclidean distances between points and closed segments in the plane, squared
// (no square root on the hot path of clearance checks, common/planning/clearance_checker.h).
#include <algorithm>

#include "common/geometry/geometry.h"

namespace fleetmap {

// Squared distance from p to the closed segment ab (a degenerate segment is a point).
inline double point_segment_distance2(Point p, Point a, Point b) {
  const Point e = b - a;
  const double len2 = dot(e, e);
  const double u = len2 > 0 ? std::clamp(dot(p - a, e) / len2, 0.0, 1.0) : 0.0;
  const Point q = a + u * e - p;
  return dot(q, q);
}

// True when the open interiors of ab and cd cross at one point (each segment has its
// ends strictly on both sides of the other's line). Touching and collinear overlaps are
// not crossings: there an end lies on the other segment, and the end distances of
// segment_distance2 are already 0.
inline bool segments_cross(Point a, Point b, Point c, Point d) {
  const double d1 = cross(b - a, c - a), d2 = cross(b - a, d - a);
  const double d3 = cross(d - c, a - c), d4 = cross(d - c, b - c);
  return ((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0));
}

// Squared distance between the closed segments ab and cd: 0 when they cross, otherwise
// the distance is reached at an end of one of them.
inline double segment_distance2(Point a, Point b, Point c, Point d) {
  if (segments_cross(a, b, c, d)) return 0;
  return std::min({point_segment_distance2(a, c, d), point_segment_distance2(b, c, d),
                   point_segment_distance2(c, a, b), point_segment_distance2(d, a, b)});
}

}  // namespace fleetmap
