// The first sweep (sweep_kernels.h): each wall against the beams it covers, one at a time.
#include <algorithm>
#include <cmath>

#include "common/raycast/beam_order.h"
#include "common/raycast/ray_caster.h"
#include "common/raycast/sweep_constants.h"
#include "common/raycast/sweep_kernels.h"

namespace fleetmap {
namespace {

// One scan being swept: its origin, beams and the nearest hit so far per beam.
struct Scan {
  Point o;
  const Point* dirs = nullptr;       // world directions, from scan_directions()
  const BeamOrder* order = nullptr;  // the beams by angle in the robot's frame
  double c = 1, s = 0;               // cos and sin of theta
  double* ranges = nullptr;
  size_t n = 0;
  double reach = 0;

  Point to_robot(Point v) const { return {c * v.x + s * v.y, c * v.y - s * v.x}; }  // rotation by -theta
  template <class Test>
  void all_beams(Test&& t) const {
    for (size_t j = 0; j < n; ++j) ranges[j] = std::min(ranges[j], t(dirs[j]));
  }
  // The beams within the pseudo-angle interval [lo, hi] whose range so far is longer
  // than `nearest`.
  template <class Test>
  void beams_between(double lo, double hi, double nearest, Test&& t) const {
    for_runs_between(*order, lo, hi, [&](size_t k0, size_t k1) {
      for (size_t k = k0; k < k1; ++k) {
        const uint32_t j = order->beam[k];
        if (ranges[j] > nearest) ranges[j] = std::min(ranges[j], t(dirs[j]));
      }
    });
  }
};

void sweep_wall(const Scan& scan, const RaySegment& w) {
  const Point a = w.a - scan.o;
  const double u = std::clamp(-dot(a, w.e) * w.inv_len2, 0.0, 1.0);
  const Point q = a + u * w.e;  // the wall's point nearest the origin
  const double d2 = dot(q, q);
  if (d2 > scan.reach * scan.reach) return;  // every hit would be past rmax
  auto test = [&](Point d) { return ray_segment_distance(w, scan.o, d); };
  if (d2 <= kSweepNear * kSweepNear) return scan.all_beams(test);
  // The wall's ends in the robot's frame, and the angle between them counter-clockwise:
  // less than pi, since the origin is not on the wall.
  const Point ar = scan.to_robot(a), er = scan.to_robot(w.e);
  double pa = pseudo_angle(ar), pb = pseudo_angle(ar + er);
  if (cross(ar, er) < 0) std::swap(pa, pb);
  if (pb < pa) pb += 4;
  // No hit on the wall is nearer than its nearest point, less the test's tolerance.
  scan.beams_between(pa - kSweepAngleSlack, pb + kSweepAngleSlack, std::sqrt(d2) - 2 * kRayTolerance, test);
}

void sweep_special(const Scan& scan, const SpecialObstacle& sp) {
  const SpecialCone cone = special_cone(sp, scan.o);
  if (cone.dist - cone.radius > scan.reach) return;
  auto test = [&](Point d) { return sp.distance(scan.o, d); };
  if (cone.dist <= cone.radius + kSweepNear) return scan.all_beams(test);
  const double pc = pseudo_angle(scan.to_robot(cone.centre)), half = cone.half_angle();
  scan.beams_between(pc - half, pc + half, cone.nearest(), test);
}

}  // namespace

void sweep_per_beam(const SweepScan& in, const std::vector<double>& relative_angles, double* ranges) {
  const size_t n = relative_angles.size();
  std::fill(ranges, ranges + n, in.rmax);
  if (in.near.empty() || n == 0) return;
  thread_local std::vector<Point> dirs;
  dirs.resize(n);
  scan_directions(in.theta, relative_angles, dirs.data());
  Scan scan;
  scan.o = in.origin;
  scan.dirs = dirs.data();
  scan.order = &beam_order(relative_angles);
  scan.c = std::cos(in.theta);
  scan.s = std::sin(in.theta);
  scan.ranges = ranges;
  scan.n = n;
  scan.reach = in.reach;
  for (const CandidateGrid::Candidate& c : in.near) {
    if (c.id < in.walls)
      sweep_wall(scan, in.obstacles->walls[c.id]);
    else
      sweep_special(scan, in.obstacles->specials[c.id - in.walls]);
  }
}

}  // namespace fleetmap
