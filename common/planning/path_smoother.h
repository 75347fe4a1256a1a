#pragma once
// Smoothing of a clear path (seed 000 Fig. 8, "the resultant smoothed path"), in three
// steps, each of which keeps every segment clear (ClearanceChecker::motion_clear) and
// never makes the path longer:
//
//   1. Greedy shortcut: from each kept waypoint, jump to the farthest later waypoint
//      that a clear straight segment reaches (replacing a sub-path by its chord is never
//      longer, by the triangle inequality).
//   2. Corner cutting: at each corner v between u and w, the largest d (by bisection)
//      for which the chord between the points at distance d from v on both legs is
//      clear, replaces v by the chord; then step 1 again. A few rounds pull the path
//      towards the shortest path of its homotopy class, which wraps the obstacles at
//      distance r.
//   3. Corner rounding (optional): each remaining corner is replaced by a circular arc
//      tangent to both legs (radius up to corner_radius, at most half of either leg),
//      drawn as chords of at most arc_step radians; an arc that is not clear is tried
//      smaller (down to tangents of 5 cm), then the corner is left sharp. Chords inside
//      the corner are shorter than the legs they replace. Corners left by step 2 wrap an
//      obstacle at distance r, a few degrees each, so there rounding mostly fails (on the
//      campus map about 3 % of corners get an arc, bench-planner): the result is a
//      polyline taut around obstacles, whose bends there are already arcs of radius
//      about r drawn by many small corners, and rounded where there is room.
//
// Deterministic: no randomness.
#include <cstddef>

#include "common/planning/clearance_checker.h"
#include "common/planning/path.h"

namespace fleetmap {

struct SmoothingOptions {
  int cut_rounds = 6;          // corner-cutting rounds (step 2); 0: greedy shortcut only
  double min_gain = 1e-3;      // metres: stop cutting when a round gains less
  bool round_corners = true;   // step 3
  double corner_radius = 1.0;  // metres: the largest arc tried
  double arc_step = 0.2;       // radians: the largest angle of one chord of an arc
};

struct SmoothingStats {
  size_t input_waypoints = 0, output_waypoints = 0;
  double input_length = 0, shortcut_length = 0, output_length = 0;
  size_t corners = 0, rounded = 0;  // corners left after step 2, of which rounded
};

class PathSmoother {
 public:
  PathSmoother(const ClearanceChecker& checker, const SmoothingOptions& options = {});

  // The path must be clear; the result starts and ends at the same points.
  Path smooth(const Path& path, SmoothingStats* stats = nullptr) const;

  Path shortcut(const Path& path) const;      // step 1
  Path cut_corners(const Path& path) const;   // steps 2 (rounds of cuts, each with step 1)
  Path round_corners(const Path& path, size_t* rounded = nullptr) const;  // step 3

 private:
  bool cut_once(Path& path) const;  // one round of cuts; false when nothing changed
  // The arc's chords replacing corner v (between u and w), or empty when none is clear.
  Path rounded_corner(Point u, Point v, Point w, double max_tangent) const;

  const ClearanceChecker& checker_;
  SmoothingOptions opt_;
};

}  // namespace fleetmap
