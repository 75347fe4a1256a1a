#include "common/raycast/ray_segment.h"

namespace fleetmap {

RaySegment prepare_segment(Point a, Point b) {
  const Point e = b - a;
  const double len2 = dot(e, e);
  const double len = std::sqrt(len2);
  // A zero-length segment (rejected by map validation) behaves as a point: only the
  // parallel branch of ray_segment_distance can reach it.
  if (len2 == 0) return {a, e, 0, 0, -1, 0};
  return {a, e, 1 / len2, kRayTolerance / len, kRayTolerance * len, 1e-12 * len};
}

}  // namespace fleetmap
