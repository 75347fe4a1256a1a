#pragma once
// Squared Euclidean distances from points, segments and rectangles to (closed)
// rectangles, for building grids: the companions of common/geometry/segment_distance.h.
#include <algorithm>

#include "common/geometry/geometry.h"
#include "common/geometry/segment_distance.h"

namespace fleetmap {

// From p to rectangle r (0 inside).
inline double squared_distance(Point p, const Rect& r) {
  const double dx = std::max({r.xmin - p.x, 0.0, p.x - r.xmax});
  const double dy = std::max({r.ymin - p.y, 0.0, p.y - r.ymax});
  return dx * dx + dy * dy;
}

// Between rectangles (0 when they meet).
inline double squared_distance(const Rect& s, const Rect& r) {
  const double dx = std::max({s.xmin - r.xmax, 0.0, r.xmin - s.xmax});
  const double dy = std::max({s.ymin - r.ymax, 0.0, r.ymin - s.ymax});
  return dx * dx + dy * dy;
}

// Does segment ab meet rectangle r? (Liang-Barsky; touching counts.)
inline bool segment_meets_rect(Point a, Point b, const Rect& r) {
  const Point d = b - a;
  double t0 = 0, t1 = 1;
  const double p[4] = {-d.x, d.x, -d.y, d.y};
  const double q[4] = {a.x - r.xmin, r.xmax - a.x, a.y - r.ymin, r.ymax - a.y};
  for (int i = 0; i < 4; ++i) {
    if (p[i] == 0) {
      if (q[i] < 0) return false;
    } else if (p[i] < 0) {
      t0 = std::max(t0, q[i] / p[i]);
    } else {
      t1 = std::min(t1, q[i] / p[i]);
    }
  }
  return t0 <= t1;
}

// From segment ab to rectangle r: 0 when they meet, else the nearest of the ends to r
// and of r's corners to the segment.
inline double squared_distance(Point a, Point b, const Rect& r) {
  if (segment_meets_rect(a, b, r)) return 0;
  double d = std::min(squared_distance(a, r), squared_distance(b, r));
  for (Point c : {Point{r.xmin, r.ymin}, Point{r.xmax, r.ymin}, Point{r.xmin, r.ymax}, Point{r.xmax, r.ymax}})
    d = std::min(d, point_segment_distance2(c, a, b));
  return d;
}

}  // namespace fleetmap
