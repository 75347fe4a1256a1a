#pragma once
// Ray against segment: where a half-line o + t d (|d| = 1, t >= 0) first meets a closed
// segment. The one intersection test of every ray caster, so that all of them give the
// same distance for the same ray and segment, bit for bit.
//
// Degenerate cases, decided once here:
//   * origin on the segment (within kRayTolerance): distance 0, whatever the direction;
//   * ray along the segment's line (parallel and within kRayTolerance of it): the
//     nearest point of the segment ahead, i.e. its nearer end;
//   * parallel and off the line: no hit;
//   * ray through an end: a hit; the end is widened by kRayTolerance so that a ray
//     through a polygon's vertex never leaks between its two segments.
#include <cmath>
#include <limits>

#include "common/geometry/geometry.h"

namespace fleetmap {

inline constexpr double kNoHit = std::numeric_limits<double>::infinity();
// Metres. Map coordinates are below 1e7 (map_validation.h) and real maps below 1e3,
// where doubles resolve ~1e-13 m: 1e-9 m is far above rounding and far below anything
// a laser or a map can tell apart.
inline constexpr double kRayTolerance = 1e-9;

// A segment prepared for ray tests: everything that depends only on the segment.
struct RaySegment {
  Point a;           // start
  Point e;           // b - a
  double inv_len2;   // 1 / |e|^2
  double tol_u;      // kRayTolerance / |e|: slack on the segment parameter
  double tol_cross;  // kRayTolerance * |e|: slack on cross products with e
  double parallel;   // 1e-12 * |e|: |cross(d, e)| below this is parallel
};

RaySegment prepare_segment(Point a, Point b);

// Distance along the ray to the segment, or kNoHit.
inline double ray_segment_distance(const RaySegment& s, Point o, Point d) {
  const Point w = s.a - o;
  const double num_t = cross(w, s.e);  // |e| times the distance of o from the line ab
  if (std::fabs(num_t) <= s.tol_cross) {
    // The origin is on the segment's line: on the segment itself means distance 0.
    const double u0 = -dot(w, s.e) * s.inv_len2;
    if (u0 >= -s.tol_u && u0 <= 1 + s.tol_u) return 0;
  }
  const double denom = cross(d, s.e);
  if (std::fabs(denom) <= s.parallel) {
    if (std::fabs(cross(d, w)) > kRayTolerance) return kNoHit;  // parallel, off the line
    const double ta = dot(w, d), tb = ta + dot(s.e, d);         // along the line
    const double lo = std::fmin(ta, tb), hi = std::fmax(ta, tb);
    if (hi < 0) return kNoHit;  // behind (the origin on it was handled above)
    return std::fmax(lo, 0.0);
  }
  const double inv = 1 / denom;
  const double t = num_t * inv;
  if (t < 0) return kNoHit;
  const double u = cross(w, d) * inv;
  if (u < -s.tol_u || u > 1 + s.tol_u) return kNoHit;
  return t;
}

inline double ray_segment_distance(Point a, Point b, Point o, Point d) {
  return ray_segment_distance(prepare_segment(a, b), o, d);
}

}  // namespace fleetmap
