#include "common/geometry/polygon.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/geometry/number_format.h"
#include "common/geometry/segment_distance.h"

namespace fleetmap {
namespace {

// --- Exact orientation (Shewchuk's expansion arithmetic) -------------------------------
// A footprint drawn by hand has collinear vertices and shared corners; a plain
// floating-point cross product can call them crossing or not at random. The sign of
// (b - a) x (c - a) is computed exactly: a fast filter first, and when the result is
// too close to zero, the whole determinant as an exact sum of doubles.

struct Two {
  double hi, lo;  // hi + lo exactly, |lo| <= ulp(hi) / 2
};

Two two_sum(double a, double b) {
  const double s = a + b;
  const double bb = s - a;
  return {s, (a - (s - bb)) + (b - bb)};
}

Two two_diff(double a, double b) { return two_sum(a, -b); }

Two two_product(double a, double b) {
  const double p = a * b;
  return {p, std::fma(a, b, -p)};
}

// Adds b to the nonoverlapping expansion e (Shewchuk's GROW-EXPANSION), in place.
void grow(std::vector<double>& e, double b) {
  double q = b;
  for (double& ei : e) {
    const Two s = two_sum(q, ei);
    ei = s.lo;
    q = s.hi;
  }
  e.push_back(q);
}

int sign_of(double v) { return (v > 0) - (v < 0); }

int orientation_exact(Point a, Point b, Point c) {
  // (bx - ax)(cy - ay) - (by - ay)(cx - ax), each difference split into hi + lo.
  const Two bx = two_diff(b.x, a.x), by = two_diff(b.y, a.y);
  const Two cx = two_diff(c.x, a.x), cy = two_diff(c.y, a.y);
  std::vector<double> e;
  e.reserve(20);
  for (double u : {bx.hi, bx.lo})
    for (double v : {cy.hi, cy.lo}) {
      const Two p = two_product(u, v);
      grow(e, p.lo);
      grow(e, p.hi);
    }
  for (double u : {by.hi, by.lo})
    for (double v : {cx.hi, cx.lo}) {
      const Two p = two_product(u, v);
      grow(e, -p.lo);
      grow(e, -p.hi);
    }
  // The most significant non-zero component carries the sign.
  for (auto it = e.rbegin(); it != e.rend(); ++it)
    if (*it != 0) return sign_of(*it);
  return 0;
}

// +1 when c lies left of the directed line ab, -1 right, 0 on it.
int orientation(Point a, Point b, Point c) {
  const double l = (b.x - a.x) * (c.y - a.y);
  const double r = (b.y - a.y) * (c.x - a.x);
  const double det = l - r;
  // Shewchuk's ccwerrboundA: beyond it the rounded sign is the exact one.
  constexpr double kEps = std::numeric_limits<double>::epsilon() / 2;
  const double bound = (3 + 16 * kEps) * kEps * (std::fabs(l) + std::fabs(r));
  if (det > bound || -det > bound) return sign_of(det);
  return orientation_exact(a, b, c);
}

// p on the closed segment ab, given that the three are collinear.
bool within_box(Point p, Point a, Point b) {
  return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
         p.y <= std::max(a.y, b.y);
}

bool on_segment(Point p, Point a, Point b) { return orientation(a, b, p) == 0 && within_box(p, a, b); }

// The closed segments ab and cd share at least one point.
bool segments_meet(Point a, Point b, Point c, Point d) {
  const int o1 = orientation(a, b, c), o2 = orientation(a, b, d);
  const int o3 = orientation(c, d, a), o4 = orientation(c, d, b);
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;
  return (o1 == 0 && within_box(c, a, b)) || (o2 == 0 && within_box(d, a, b)) ||
         (o3 == 0 && within_box(a, c, d)) || (o4 == 0 && within_box(b, c, d));
}

std::string show(Point p) { return std::string("(") + format_number(p.x) + ", " + format_number(p.y) + ")"; }

// Vertices and edges are numbered from 1 in messages; edge i runs from vertex i to i+1.
std::string vertex_name(size_t i) { return "vertex " + std::to_string(i + 1); }
std::string edge_name(size_t i, size_t n) {
  return "edge " + std::to_string(i + 1) + " (vertices " + std::to_string(i + 1) + "-" + std::to_string((i + 1) % n + 1) + ")";
}

}  // namespace

std::optional<std::string> polygon_problem(const Polygon& ring) {
  const size_t n = ring.size();
  for (size_t i = 0; i < n; ++i)
    if (!std::isfinite(ring[i].x) || !std::isfinite(ring[i].y))
      return "expected finite coordinates, got a NaN or infinity at " + vertex_name(i);

  std::vector<Point> distinct(ring);
  std::sort(distinct.begin(), distinct.end(), [](Point a, Point b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
  if (distinct.size() < 3)
    return "expected at least 3 distinct points, got " + std::to_string(distinct.size());

  for (size_t i = 0; i < n; ++i)
    if (ring[i] == ring[(i + 1) % n])
      return "expected no repeated consecutive points, got " + vertex_name(i) + " and " +
             ((i + 1) % n == 0 ? std::string("the first") : vertex_name(i + 1)) + " both at " + show(ring[i]);

  bool flat = true;
  for (size_t i = 2; i < n && flat; ++i) flat = orientation(ring[0], ring[1], ring[i]) == 0;
  if (flat) return "expected a non-zero area, got every point on one line";

  // Adjacent edges share a vertex; they must not fold back over each other (a spike).
  for (size_t i = 0; i < n; ++i) {
    const Point a = ring[(i + n - 1) % n], v = ring[i], b = ring[(i + 1) % n];
    if (orientation(a, v, b) == 0 && dot(v - a, b - v) < 0)
      return "expected a simple ring, got a spike at " + vertex_name(i) + " " + show(v) +
             " (its two edges overlap)";
  }
  // Any other two edges must not meet at all. O(n^2): footprints and areas are small.
  for (size_t i = 0; i < n; ++i) {
    const Point a = ring[i], b = ring[(i + 1) % n];
    for (size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;  // edges n and 1 are adjacent
      if (segments_meet(a, b, ring[j], ring[(j + 1) % n]))
        return "expected a simple ring, got " + edge_name(i, n) + " and " + edge_name(j, n) + " crossing or touching";
    }
  }
  return std::nullopt;
}

bool point_in_polygon(Point p, const Polygon& ring) {
  const size_t n = ring.size();
  bool inside = false;
  for (size_t i = 0; i < n; ++i) {
    const Point a = ring[i], b = ring[(i + 1) % n];
    if (on_segment(p, a, b)) return true;
    // Crossing number along +x, half-open in y so a vertex is counted once.
    if ((a.y > p.y) != (b.y > p.y)) {
      const int o = orientation(a, b, p);
      if ((b.y > a.y) ? o > 0 : o < 0) inside = !inside;
    }
  }
  return inside;
}

double distance_to_polygon(Point p, const Polygon& ring) {
  if (ring.empty()) return std::numeric_limits<double>::infinity();
  if (point_in_polygon(p, ring)) return 0;
  double d2 = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < ring.size(); ++i)
    d2 = std::min(d2, point_segment_distance2(p, ring[i], ring[(i + 1) % ring.size()]));
  return std::sqrt(d2);
}

double polygon_area(const Polygon& ring) {
  // Shoelace relative to the first vertex: far from the origin, fewer digits are lost.
  double twice = 0;
  for (size_t i = 1; i + 1 < ring.size(); ++i) twice += cross(ring[i] - ring[0], ring[i + 1] - ring[0]);
  return std::fabs(twice) / 2;
}

Rect polygon_bounds(const Polygon& ring) {
  if (ring.empty()) return {};
  Rect r = Rect::none();
  for (Point p : ring) r.extend(p);
  return r;
}

Polygon rectangle_footprint(Point c, double w, double h, double yaw) {
  const double cs = std::cos(yaw), sn = std::sin(yaw);
  Polygon out;
  // Counter-clockwise from the corner at (-w/2, -h/2) in the rectangle's own frame.
  for (auto [u, v] : {std::pair{-w / 2, -h / 2}, {w / 2, -h / 2}, {w / 2, h / 2}, {-w / 2, h / 2}})
    out.push_back({c.x + cs * u - sn * v, c.y + sn * u + cs * v});
  return out;
}

}  // namespace fleetmap
