#include "common/raycast/occlusion.h"

#include <cmath>

namespace fleetmap {
namespace {

// Signed distance of p from the line through a along the unit vector u (left > 0).
inline double side(Point a, Point u, Point p) { return cross(u, p - a); }

}  // namespace

bool hides(const RaySegment& occluder, const RaySegment& wall, const Rect& cell) {
  // What the test below implies for the cell's centre alone, without margins and
  // square roots: most pairs fail it.
  const Point o1 = occluder.a, o2 = occluder.a + occluder.e;
  const Point c{(cell.xmin + cell.xmax) / 2, (cell.ymin + cell.ymax) / 2};
  const double sc = cross(occluder.e, c - o1);
  for (const Point q : {wall.a, wall.a + wall.e}) {
    if (!(sc * cross(occluder.e, q - o1) < 0)) return false;
    const Point v = q - c;
    if (!(cross(v, o1 - c) * cross(v, o2 - c) < 0)) return false;
  }
  const double m = kOcclusionMargin;
  const double olen = std::sqrt(dot(occluder.e, occluder.e));
  const double wlen = std::sqrt(dot(wall.e, wall.e));
  if (olen <= 4 * m || wlen == 0) return false;
  const Point ou = (1 / olen) * occluder.e, wu = (1 / wlen) * wall.e;
  const Point corners[4] = {
      {cell.xmin - m, cell.ymin - m}, {cell.xmax + m, cell.ymin - m}, {cell.xmin - m, cell.ymax + m},
      {cell.xmax + m, cell.ymax + m}};
  const Point ends[2] = {wall.a - m * wu, wall.a + wall.e + m * wu};
  // The cell wholly on one side of O's line, the wall's ends on the other, by m.
  const double s0 = side(o1, ou, corners[0]);
  const double sign = s0 > 0 ? 1 : -1;
  for (const Point& p : corners)
    if (sign * side(o1, ou, p) <= m) return false;
  for (const Point& q : ends)
    if (sign * side(o1, ou, q) >= -m) return false;
  // Each corner-to-end line passes between O's ends, both farther than m from it.
  for (const Point& p : corners)
    for (const Point& q : ends) {
      const Point v = q - p;
      const double len = std::sqrt(dot(v, v));
      if (len <= m) return false;
      const Point vu = (1 / len) * v;
      const double a = side(p, vu, o1), b = side(p, vu, o2);
      if (!((a > m && b < -m) || (a < -m && b > m))) return false;
    }
  return true;
}

}  // namespace fleetmap
