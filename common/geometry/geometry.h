#pragma once
// Plane geometry in the map frame (metres): points, rectangles, segment clipping.
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace fleetmap {

struct Point {
  double x = 0;
  double y = 0;
  friend bool operator==(const Point&, const Point&) = default;
};

inline Point operator+(Point a, Point b) { return {a.x + b.x, a.y + b.y}; }
inline Point operator-(Point a, Point b) { return {a.x - b.x, a.y - b.y}; }
inline Point operator*(double k, Point a) { return {k * a.x, k * a.y}; }
inline double dot(Point a, Point b) { return a.x * b.x + a.y * b.y; }
inline double cross(Point a, Point b) { return a.x * b.y - a.y * b.x; }
inline double norm(Point a) { return std::hypot(a.x, a.y); }
inline double distance(Point a, Point b) { return norm(b - a); }

// Axis-aligned rectangle, xmin <= xmax and ymin <= ymax.
struct Rect {
  double xmin = 0, ymin = 0, xmax = 0, ymax = 0;
  static Rect centred(Point c, double w, double h) {
    return {c.x - w / 2, c.y - h / 2, c.x + w / 2, c.y + h / 2};
  }
  bool empty() const { return !(xmin < xmax && ymin < ymax); }
  bool contains(Point p) const { return p.x >= xmin && p.x <= xmax && p.y >= ymin && p.y <= ymax; }
  // A box holding nothing (inverted, it meets nothing); extend() grows it to hold p.
  static Rect none() {
    const double inf = std::numeric_limits<double>::infinity();
    return {inf, inf, -inf, -inf};
  }
  void extend(Point p) {
    xmin = std::min(xmin, p.x);
    ymin = std::min(ymin, p.y);
    xmax = std::max(xmax, p.x);
    ymax = std::max(ymax, p.y);
  }
  friend bool operator==(const Rect&, const Rect&) = default;
};

inline Rect intersection(const Rect& a, const Rect& b) {
  return {std::fmax(a.xmin, b.xmin), std::fmax(a.ymin, b.ymin), std::fmin(a.xmax, b.xmax),
          std::fmin(a.ymax, b.ymax)};
}

struct ClippedSegment {
  Point a, b;
};

// Liang–Barsky: the part of segment ab inside r, or nothing when that part has
// zero length (a segment that only touches the rectangle is not in it). An end that
// lies inside r is returned unchanged (bit for bit), so unclipped segments survive exactly.
std::optional<ClippedSegment> clip_segment(Point a, Point b, const Rect& r);

}  // namespace fleetmap
