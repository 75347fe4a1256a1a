#include "common/raycast/occlusion.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <span>
#include <utility>

namespace fleetmap {
namespace {

// Signed distance of p from the line through a along the unit vector u (left > 0).
inline double side(Point a, Point u, Point p) { return cross(u, p - a); }

// Whether the axis n (any length) separates the triangle from the points by more than m.
bool separates(Point n, std::span<const Point> triangle, std::span<const Point> points, double m) {
  const double len = std::sqrt(dot(n, n));
  if (len == 0) return false;
  auto span_of = [&](std::span<const Point> ps) {
    double lo = dot(n, ps[0]), hi = lo;
    for (const Point& p : ps) lo = std::min(lo, dot(n, p)), hi = std::max(hi, dot(n, p));
    return std::pair{lo, hi};
  };
  const auto [tlo, thi] = span_of(triangle);
  const auto [plo, phi] = span_of(points);
  return plo > thi + m * len || phi < tlo - m * len;
}

// Whether the triangle lies farther than m from the convex hull of the points: an axis
// among the triangle's edge normals and `extra` separates them.
bool clear_of(std::span<const Point> triangle, std::span<const Point> points, std::span<const Point> extra,
              double m) {
  for (int i = 0; i < 3; ++i) {
    const Point e = triangle[(i + 1) % 3] - triangle[i];
    if (separates({-e.y, e.x}, triangle, points, m)) return true;
  }
  for (const Point& n : extra)
    if (separates(n, triangle, points, m)) return true;
  return false;
}

// Whether every corner lies on one side of the occluder's line, farther than `slope`
// times `far`: a ray from the cell meets the line at a sine of at least slope.
bool off_line(const RaySegment& o, std::span<const Point> corners, double far, double slope) {
  const double len = std::sqrt(dot(o.e, o.e));
  double lo = cross(o.e, corners[0] - o.a), hi = lo;
  for (const Point& p : corners) lo = std::min(lo, cross(o.e, p - o.a)), hi = std::max(hi, cross(o.e, p - o.a));
  const double need = slope * far * len;
  return lo > need || hi < -need;
}

// Corners of the cell grown by m.
std::array<Point, 4> grown_corners(const Rect& cell, double m) {
  return {Point{cell.xmin - m, cell.ymin - m}, Point{cell.xmax + m, cell.ymin - m}, Point{cell.xmin - m, cell.ymax + m},
          Point{cell.xmax + m, cell.ymax + m}};
}

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

bool hides_joint(const RaySegment& first, const RaySegment& second, const RaySegment& wall, const Rect& cell) {
  const Point f[2] = {first.a, first.a + first.e}, s[2] = {second.a, second.a + second.e};
  int i = -1, j = -1;
  for (int x = 0; x < 2 && i < 0; ++x)
    for (int y = 0; y < 2; ++y)
      if (f[x].x == s[y].x && f[x].y == s[y].y) {
        i = x, j = y;
        break;
      }
  if (i < 0) return false;
  const Point a = f[1 - i], b = f[i], c = s[1 - j];
  if (a.x == c.x && a.y == c.y) return false;
  const double m = kOcclusionMargin;
  // Sine 1e-3 between any ray from the cell and AB or BC: the crossing's position is
  // then off by less than 1e-10 m where coordinates stay below 1e3 m (ray_segment.h).
  constexpr double kSlope = 1e-3;
  const std::array<Point, 4> corners = grown_corners(cell, m);
  const double wlen = std::sqrt(dot(wall.e, wall.e));
  if (wlen == 0) return false;
  const Point wu = (1 / wlen) * wall.e;
  const std::array<Point, 2> ends = {wall.a - m * wu, wall.a + wall.e + m * wu};
  double far = 0;
  for (const Point& p : corners)
    for (const Point& q : ends) far = std::max(far, dot(q - p, q - p));
  far = std::sqrt(far);
  if (!off_line(first, corners, far, kSlope) || !off_line(second, corners, far, kSlope)) return false;
  // The chord hides W: every ray from the cell to W crosses AC at X, away from A and C.
  if (!hides(prepare_segment(a, c), wall, cell)) return false;
  // X lies in the closed triangle ABC and the ray's ends outside it, farther than m: the
  // ray meets the triangle's outline on AB or BC (its one crossing of AC's line is X,
  // and X itself is on AB or BC when the triangle is flat), strictly before W.
  const std::array<Point, 3> triangle = {a, b, c};
  const Point cell_axes[2] = {{1, 0}, {0, 1}};
  const Point wall_axis[1] = {{-wall.e.y, wall.e.x}};
  return clear_of(triangle, corners, cell_axes, m) && clear_of(triangle, ends, wall_axis, m);
}

}  // namespace fleetmap
