#include "common/planning/path_smoother.h"

#include <algorithm>
#include <cmath>

namespace fleetmap {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kBisections = 12;       // corner cut: d known to dmax / 4096
constexpr double kMinCutGain = 1e-3;  // metres: a cut that gains less is not worth a waypoint
constexpr int kRoundingTries = 4;     // arc tangent lengths t, t/2, t/4, t/8
constexpr double kMinTangent = 0.05;  // metres: a smaller arc is not worth its waypoints

Point unit(Point v) { return (1 / norm(v)) * v; }

// Appends p unless it repeats the last point.
void push(Path& path, Point p) {
  if (path.empty() || !(path.back() == p)) path.push_back(p);
}

}  // namespace

PathSmoother::PathSmoother(const ClearanceChecker& checker, const SmoothingOptions& options)
    : checker_(checker), opt_(options) {}

Path PathSmoother::smooth(const Path& path, SmoothingStats* stats) const {
  Path p = cut_corners(path);
  const double shortcut_length = path_length(p);
  const size_t corners = p.size() >= 2 ? p.size() - 2 : 0;
  size_t rounded = 0;
  if (opt_.round_corners) p = round_corners(p, &rounded);
  if (stats) {
    *stats = {path.size(), p.size(), path_length(path), shortcut_length, path_length(p), corners, rounded};
  }
  return p;
}

Path PathSmoother::shortcut(const Path& path) const {
  if (path.size() <= 2) return path;
  Path out{path.front()};
  for (size_t i = 0; i + 1 < path.size();) {
    size_t j = path.size() - 1;
    while (j > i + 1 && !checker_.motion_clear(path[i], path[j])) --j;
    push(out, path[j]);
    i = j;
  }
  return out;
}

bool PathSmoother::cut_once(Path& path) const {
  if (path.size() <= 2) return false;
  bool changed = false;
  Path out{path.front()};
  for (size_t k = 1; k + 1 < path.size(); ++k) {
    // out.back() lies on the leg into v (where the previous cut ended), so the leg from
    // it to v is part of a clear segment.
    const Point u = out.back(), v = path[k], w = path[k + 1];
    const double lu = distance(u, v), lw = distance(v, w);
    if (lu == 0 || lw == 0) {
      push(out, v);
      continue;
    }
    const Point du = (1 / lu) * (u - v), dw = (1 / lw) * (w - v);
    auto chord_clear = [&](double d) { return checker_.motion_clear(v + d * du, v + d * dw); };
    double lo = 0, hi = std::min(lu, lw);
    if (chord_clear(hi)) {
      lo = hi;
    } else {
      for (int b = 0; b < kBisections; ++b) {
        const double mid = 0.5 * (lo + hi);
        (chord_clear(mid) ? lo : hi) = mid;
      }
    }
    const Point a = v + lo * du, c = v + lo * dw;
    if (lo > 0 && 2 * lo - distance(a, c) > kMinCutGain) {
      push(out, a);
      push(out, c);
      changed = true;
    } else {
      push(out, v);
    }
  }
  push(out, path.back());
  path = std::move(out);
  return changed;
}

Path PathSmoother::cut_corners(const Path& path) const {
  Path p = shortcut(path);
  for (int round = 0; round < opt_.cut_rounds; ++round) {
    const double before = path_length(p);
    if (!cut_once(p)) break;
    p = shortcut(p);
    if (before - path_length(p) < opt_.min_gain) break;
  }
  return p;
}

Path PathSmoother::rounded_corner(Point u, Point v, Point w, double max_tangent) const {
  const Point du = unit(u - v), dw = unit(w - v);
  const double turn = kPi - std::acos(std::clamp(dot(du, dw), -1.0, 1.0));
  // Nearly straight: nothing to round; nearly a U-turn: the arc's centre is ill-defined.
  if (turn < 1e-3 || turn > kPi - 1e-3) return {};
  const double tan_half = std::tan(turn / 2);
  const double sense = cross(v - u, w - v) > 0 ? 1 : -1;  // left turns go counter-clockwise
  const Point bisector = unit(du + dw);
  const int chords = std::max(1, static_cast<int>(std::ceil(turn / opt_.arc_step)));
  double t = std::min(opt_.corner_radius * tan_half, max_tangent);
  for (int attempt = 0; attempt < kRoundingTries && t >= kMinTangent; ++attempt, t *= 0.5) {
    const double rho = t / tan_half;
    const Point a = v + t * du, b = v + t * dw;
    const Point c = v + std::sqrt(t * t + rho * rho) * bisector;
    const double start = std::atan2(a.y - c.y, a.x - c.x);
    Path arc{a};
    for (int i = 1; i < chords; ++i) {
      const double ang = start + sense * turn * i / chords;
      arc.push_back({c.x + rho * std::cos(ang), c.y + rho * std::sin(ang)});
    }
    arc.push_back(b);
    bool clear = true;
    for (size_t i = 1; i < arc.size() && clear; ++i) clear = checker_.motion_clear(arc[i - 1], arc[i]);
    if (clear) return arc;
  }
  return {};
}

Path PathSmoother::round_corners(const Path& path, size_t* rounded) const {
  if (rounded) *rounded = 0;
  if (path.size() <= 2) return path;
  Path out{path.front()};
  for (size_t k = 1; k + 1 < path.size(); ++k) {
    // The previous arc used at most half of the leg into v; this one may use the rest of
    // it and half of the leg out of v, leaving the other half to the next corner.
    const Point u = out.back(), v = path[k], w = path[k + 1];
    const double lu = distance(u, v), lw = distance(v, w);
    Path arc;
    if (lu > 0 && lw > 0) arc = rounded_corner(u, v, w, std::min(lu, 0.5 * lw));
    if (arc.empty()) {
      push(out, v);
      continue;
    }
    for (Point p : arc) push(out, p);
    if (rounded) ++*rounded;
  }
  push(out, path.back());
  return out;
}

}  // namespace fleetmap
