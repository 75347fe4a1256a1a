#pragma once
// Shared by the planning tests (clearance_checker, rrt_connect, path_smoother,
// grid_astar, map_planner): the real maps, and a clearance judge written independently
// of common/clearance_checker and common/segment_distance, by brute force over every
// blocking segment of the map with a different exact distance formula.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "common/io/amrl_import.h"
#include "common/planning/grid_astar.h"
#include "common/map/map.h"
#include "common/planning/path.h"

namespace fleetmap::planning_test {

inline const Map& gdc1() {
  static const Map m = read_amrl_file(FLEETMAP_REAL_MAPS "/GDC1.vectormap.txt", AmrlOptions{});
  return m;
}

inline const Map& ut_campus() {
  static const Map m = read_amrl_file(FLEETMAP_REAL_MAPS "/UT_Campus.vectormap.txt", AmrlOptions{});
  return m;
}

// Squared distance between segments p0p1 and q0q1: the minimum of |P(s) - Q(t)|^2 over
// s, t in [0, 1], solved as in Ericson, Real-Time Collision Detection §5.1.9 (clamped
// stationary point of the quadratic, parallel case included). Crossing segments give 0.
inline double brute_segment_distance2(Point p0, Point p1, Point q0, Point q1) {
  const Point d1 = p1 - p0, d2 = q1 - q0, r = p0 - q0;
  const double a = dot(d1, d1), e = dot(d2, d2), f = dot(d2, r);
  double s = 0, t = 0;
  if (a <= 1e-300 && e <= 1e-300) {
    s = t = 0;
  } else if (a <= 1e-300) {
    t = std::clamp(f / e, 0.0, 1.0);
  } else {
    const double c = dot(d1, r);
    if (e <= 1e-300) {
      s = std::clamp(-c / a, 0.0, 1.0);
    } else {
      const double b = dot(d1, d2), denom = a * e - b * b;
      s = denom > 0 ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
      t = (b * s + f) / e;
      if (t < 0) {
        t = 0;
        s = std::clamp(-c / a, 0.0, 1.0);
      } else if (t > 1) {
        t = 1;
        s = std::clamp((b - c) / a, 0.0, 1.0);
      }
    }
  }
  const Point diff = (p0 + s * d1) - (q0 + t * d2);
  return dot(diff, diff);
}

// The planner's blocking rule restated for maps of ST 1-4 obstacles only (the real maps,
// every segment 2 m high): a segment blocks when h > 0.
struct BruteClearance {
  std::vector<std::pair<Point, Point>> walls;
  Rect border;
  explicit BruteClearance(const Map& m) : border(m.border.rect()) {
    for (const Obstacle& o : m.obstacles) {
      EXPECT_LE(static_cast<int>(o.type), 4) << "BruteClearance handles ST 1-4 only";
      for (const Segment& s : o.segments)
        if (s.h > 0) walls.emplace_back(s.a, s.b);
    }
  }
  // Distance from the motion ab to the nearest wall, and to the border's inside.
  double clearance(Point a, Point b) const {
    double d2 = std::numeric_limits<double>::infinity();
    for (const auto& [c, d] : walls) d2 = std::min(d2, brute_segment_distance2(a, b, c, d));
    double d = std::sqrt(d2);
    for (Point p : {a, b})  // the border rectangle is convex: its ends decide
      d = std::min({d, p.x - border.xmin, border.xmax - p.x, p.y - border.ymin, border.ymax - p.y});
    return d;
  }
  double path_clearance(const Path& path) const {
    double d = std::numeric_limits<double>::infinity();
    for (size_t i = 1; i < path.size(); ++i) d = std::min(d, clearance(path[i - 1], path[i]));
    if (path.size() == 1) d = clearance(path[0], path[0]);
    return d;
  }
};

struct QueryPair {
  Point start, goal;
  double astar_length;
};

// Random start/goal pairs that are clear (brute force) and that the grid A* joins, so a
// path surely exists (grid_astar.h). Seeded.
inline std::vector<QueryPair> reachable_pairs(const Map& m, double radius, size_t n, unsigned seed,
                                              double resolution) {
  const BruteClearance judge(m);
  GridAStar astar(m, {resolution, radius, {}});
  std::mt19937_64 rng(seed);
  const Rect b = m.border.rect();
  std::uniform_real_distribution<double> ux(b.xmin, b.xmax), uy(b.ymin, b.ymax);
  std::vector<QueryPair> out;
  for (size_t tries = 0; out.size() < n && tries < 200 * n; ++tries) {
    const Point s{ux(rng), uy(rng)}, g{ux(rng), uy(rng)};
    if (judge.clearance(s, s) <= radius || judge.clearance(g, g) <= radius) continue;
    if (const auto p = astar.solve(s, g)) out.push_back({s, g, path_length(*p)});
  }
  EXPECT_EQ(out.size(), n) << "not enough reachable pairs";
  return out;
}

}  // namespace fleetmap::planning_test
