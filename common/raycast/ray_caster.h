#pragma once
// Synthetic laser rays on the segment map (SPEC 6, seed 000 section 4.1).
//
// A 2D laser mounted laser_height metres over the floor casts rays from a point of the
// map plane; a ray ends at the first obstacle that stops it, or at rmax when nothing
// does. What stops a ray (walls lower than the laser, stairs seen from above or below,
// ramps) is decided by common/raycast/ray_rules.h, shared by every implementation, and every
// one meets segments through the same exact test (common/raycast/ray_segment.h):
//
//   SeedRayCaster   (seed_ray_caster.h)   the seed's method, the reference: per-obstacle
//                   minimum bounding circles culled against the scanner's circle.
//   SweepRayCaster  (sweep_ray_caster.h)  the fast one: per-cell lists of what lies
//                   within rmax, swept over a scan's beams by angle.
//   GridRayCaster   (grid_ray_caster.h)   rays walk a uniform grid of segments; memory
//                   independent of rmax, the fallback of make_fast_ray_caster().
//
// They give the same ranges (tests/common/raycast/ray_caster_equivalence_test.cpp: within 1e-6 m,
// in practice bit for bit) and are immutable after construction, so one instance
// serves any number of threads. bench/bench_raycast.cpp compares their speed.
#include <cmath>
#include <vector>

#include "common/geometry/geometry.h"

namespace fleetmap {

struct RayCasterOptions {
  double laser_height = 0.3;  // hL, metres over the floor
  double rmax = 15.0;         // metres: seed 000 section 4.1, RMAX
};

class RayCaster {
 public:
  virtual ~RayCaster() = default;

  // Range along the ray from origin at angle (radians, from +x counter-clockwise), in
  // [0, rmax]: rmax when nothing stops the ray within rmax.
  double cast(Point origin, double angle) const;

  // The same along a unit direction vector.
  virtual double cast_direction(Point origin, Point dir) const = 0;

  // One scan: ranges[i] for the ray at theta + relative_angles[i]. The directions come
  // from scan_directions(), so every implementation casts exactly the same rays. The
  // default casts them one by one.
  virtual void cast_scan(Point origin, double theta, const std::vector<double>& relative_angles, double* ranges) const;

  virtual const RayCasterOptions& options() const = 0;
};

// The unit direction of a single ray, as cast() uses it.
inline Point ray_direction(double angle) { return {std::cos(angle), std::sin(angle)}; }

// dirs[i] = the unit vector at theta + relative_angles[i], computed as the rotation by
// theta of (cos, sin) of relative_angles[i] (equal to ray_direction(theta + rel) within
// a few units in the last place). The cosines and sines of the relative angles are
// kept per thread for the last vector seen, so a filter that casts thousands of scans
// with the same beams pays one sine and cosine per scan, not per ray.
void scan_directions(double theta, const std::vector<double>& relative_angles, Point* dirs);

// n angles evenly spread over fov radians, centred on 0 (the seed's laser: 131 over pi).
std::vector<double> evenly_spread_angles(int n, double fov);

}  // namespace fleetmap
