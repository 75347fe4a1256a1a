#pragma once
// A scan's beams ordered by angle, for the sweep casters (sweep_ray_caster.h): a wall
// seen from the origin covers an interval of angles, and the beams inside it are a run
// of consecutive positions in this order (two runs when the interval wraps).
//
// Angles are pseudo-angles (pseudo_angle below), a division instead of atan2, and a
// table over them replaces binary searches (their mispredicted branches were most of a
// scan's time on dense maps). The order is kept per thread for the last beam set seen,
// like scan_directions(): a filter casts thousands of scans with the same beams.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "common/geometry/geometry.h"

namespace fleetmap {

// Pseudo-angle of (x, y) in [0, 4): grows with the angle from +x counter-clockwise, as
// atan2 does, at a rate between 1/2 and 1 per radian.
// Written as selects of constants (2 - r, 4 + r or r), which compile without branches:
// the sweeps call it on walls in no predictable order.
inline double pseudo_angle(Point v) {
  const double r = v.y / (std::fabs(v.x) + std::fabs(v.y));
  const double base = v.x < 0 ? 2.0 : (v.y < 0 ? 4.0 : 0.0);
  const double sign = v.x < 0 ? -1.0 : 1.0;
  return base + sign * r;
}

struct BeamOrder {
  static constexpr int kBinsPerUnit = 1024;
  static constexpr int kBins = 4 * kBinsPerUnit;
  std::vector<double> angles;   // the relative angles this was built for
  std::vector<double> pseudo;   // of the relative directions (robot's frame), sorted
  std::vector<uint32_t> beam;   // beam[k]: the beam with the k-th pseudo-angle
  // (unit_x[k], unit_y[k]): ray_direction() of that beam's relative angle, by coordinate
  // for vector loads; n rounded up to a multiple of 4, zeros after.
  std::vector<double> unit_x, unit_y;
  std::vector<uint32_t> first;  // first[b]: how many pseudo-angles are below b / kBinsPerUnit
  // The smallest arc holding every beam runs counter-clockwise from position arc_first
  // to position arc_last; all_around when the beams leave no gap worth testing against.
  size_t arc_first = 0, arc_last = 0;
  bool all_around = true;
  // No bin of the table holds two beams: lower() takes at most one step from first[].
  bool one_per_bin = false;
  // beam[k] is (k + rotation) % n for every k (beams given by angle, as scans are), or
  // this is false.
  bool rotated = false;
  size_t rotation = 0;

  // The first k with pseudo[k] >= x (strict: > x), for x in [0, 4].
  size_t lower(double x, bool strict) const {
    size_t k = first[std::clamp(static_cast<int>(x * kBinsPerUnit), 0, kBins)];
    while (k < pseudo.size() && (strict ? pseudo[k] <= x : pseudo[k] < x)) ++k;
    return k;
  }
};

// The order of these relative angles (cached per thread; valid until the next call
// with other angles on the same thread).
const BeamOrder& beam_order(const std::vector<double>& relative_angles);

// Calls run(k0, k1) for each run [k0, k1) of positions whose pseudo-angle lies in
// [lo, hi] modulo 4 (at most two runs).
template <class F>
[[gnu::always_inline]] inline void for_runs_between(const BeamOrder& order, double lo, double hi, F&& run) {
  auto one = [&](double a, double b) __attribute__((always_inline)) {
    const size_t k0 = order.lower(a, false), k1 = order.lower(b, true);
    if (k0 < k1) run(k0, k1);
  };
  if (hi - lo >= 4) {
    one(0, 4);
  } else if (lo < 0) {
    one(lo + 4, 4);
    one(0, hi);
  } else if (hi >= 4) {
    one(lo, 4);
    one(0, hi - 4);
  } else {
    one(lo, hi);
  }
}

}  // namespace fleetmap
