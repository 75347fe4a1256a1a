#include "common/geometry/geometry.h"

namespace fleetmap {

std::optional<ClippedSegment> clip_segment(Point a, Point b, const Rect& r) {
  const Point d = b - a;
  double t0 = 0, t1 = 1;
  // One (p, q) pair per rectangle edge: the segment is inside that edge where p*t <= q.
  const double p[4] = {-d.x, d.x, -d.y, d.y};
  const double q[4] = {a.x - r.xmin, r.xmax - a.x, a.y - r.ymin, r.ymax - a.y};
  for (int i = 0; i < 4; ++i) {
    if (p[i] == 0) {
      if (q[i] < 0) return std::nullopt;  // parallel to this edge and outside it
      continue;
    }
    const double t = q[i] / p[i];
    if (p[i] < 0) {
      if (t > t1) return std::nullopt;
      if (t > t0) t0 = t;
    } else {
      if (t < t0) return std::nullopt;
      if (t < t1) t1 = t;
    }
  }
  if (!(t0 < t1)) return std::nullopt;
  // a + t*d can land one rounding step outside r; a cut end belongs on r's edge.
  auto on_rect = [&r](Point p) {
    return Point{std::fmin(std::fmax(p.x, r.xmin), r.xmax), std::fmin(std::fmax(p.y, r.ymin), r.ymax)};
  };
  ClippedSegment out{t0 == 0 ? a : on_rect(a + t0 * d), t1 == 1 ? b : on_rect(a + t1 * d)};
  if (out.a == out.b) return std::nullopt;
  return out;
}

}  // namespace fleetmap
