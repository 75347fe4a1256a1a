#include "common/raycast/sweep_ray_caster.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numeric>

#include "common/raycast/grid_ray_caster.h"

namespace fleetmap {
namespace {

// A wall nearer the origin than this is tested against every beam: the angle it
// subtends is then ill-conditioned (and it may hold the origin).
constexpr double kNear = 1e-3;  // metres
// Slack on a wall's angular interval, in pseudo-angle units (at least radians): far
// above rounding, and above the kRayTolerance / kNear = 1e-6 rad by which the exact
// test widens a wall's ends.
constexpr double kAngleSlack = 1e-5;

// A wall whose ends are farther than this from a ray's line, both on the same side,
// cannot be hit: the exact test widens a wall's ends by kRayTolerance only.
constexpr double kSideSlack = 4 * kRayTolerance;

// Pseudo-angle of (x, y) in [0, 4): grows with the angle from +x counter-clockwise, as
// atan2 does, at a rate between 1/2 and 1 per radian; a division instead of atan2.
inline double pseudo_angle(Point v) {
  const double r = v.y / (std::fabs(v.x) + std::fabs(v.y));
  return v.x < 0 ? 2 - r : (v.y < 0 ? 4 + r : r);
}

// The beams sorted by the pseudo-angle of their relative direction (the robot's
// frame), kept per thread for the last beam set seen, like scan_directions(). A table
// over the pseudo-angle replaces binary searches (their mispredicted branches were
// most of a scan's time on dense maps).
struct BeamOrder {
  static constexpr int kBinsPerUnit = 1024;
  static constexpr int kBins = 4 * kBinsPerUnit;
  std::vector<double> angles;   // the relative angles this was built for
  std::vector<double> pseudo;   // sorted
  std::vector<uint32_t> beam;   // beam[k]: the beam with the k-th pseudo-angle
  std::vector<uint32_t> first;  // first[b]: how many pseudo-angles are below b / kBinsPerUnit

  // The first k with pseudo[k] >= x (strict: > x), for x in [0, 4].
  size_t lower(double x, bool strict) const {
    size_t k = first[std::clamp(static_cast<int>(x * kBinsPerUnit), 0, kBins)];
    while (k < pseudo.size() && (strict ? pseudo[k] <= x : pseudo[k] < x)) ++k;
    return k;
  }
};

const BeamOrder& beam_order(const std::vector<double>& rel) {
  thread_local BeamOrder order;
  const size_t n = rel.size();
  if (order.angles.size() == n && !order.first.empty() &&
      (n == 0 || std::memcmp(order.angles.data(), rel.data(), n * sizeof(double)) == 0))
    return order;
  order.angles = rel;
  std::vector<double> p(n);
  for (size_t j = 0; j < n; ++j) p[j] = pseudo_angle(ray_direction(rel[j]));
  order.beam.resize(n);
  std::iota(order.beam.begin(), order.beam.end(), 0u);
  std::stable_sort(order.beam.begin(), order.beam.end(), [&](uint32_t l, uint32_t r) { return p[l] < p[r]; });
  order.pseudo.resize(n);
  for (size_t k = 0; k < n; ++k) order.pseudo[k] = p[order.beam[k]];
  order.first.resize(BeamOrder::kBins + 1);
  for (int b = 0; b <= BeamOrder::kBins; ++b)
    order.first[b] = static_cast<uint32_t>(
        std::lower_bound(order.pseudo.begin(), order.pseudo.end(), static_cast<double>(b) / BeamOrder::kBinsPerUnit) -
        order.pseudo.begin());
  return order;
}

// Calls f(beam) for every beam whose pseudo-angle lies in [lo, hi] modulo 4.
template <class F>
void for_beams_between(const BeamOrder& order, double lo, double hi, F&& f) {
  auto run = [&](double a, double b) {
    for (size_t k = order.lower(a, false), end = order.lower(b, true); k < end; ++k) f(order.beam[k]);
  };
  if (hi - lo >= 4) {
    run(0, 4);
  } else if (lo < 0) {
    run(lo + 4, 4);
    run(0, hi);
  } else if (hi >= 4) {
    run(lo, 4);
    run(0, hi - 4);
  } else {
    run(lo, hi);
  }
}

// One scan being swept: its origin, beams and the nearest hit so far per beam.
struct Scan {
  Point o;
  const Point* dirs = nullptr;       // world directions, from scan_directions()
  const BeamOrder* order = nullptr;  // the beams by angle in the robot's frame
  double c = 1, s = 0;               // cos and sin of theta
  double* ranges = nullptr;
  size_t n = 0;
  double reach = 0;  // rmax and a hair: nothing farther can shorten a range

  Point to_robot(Point v) const { return {c * v.x + s * v.y, c * v.y - s * v.x}; }  // rotation by -theta
  template <class Test>
  void all_beams(Test&& t) const {
    for (size_t j = 0; j < n; ++j) ranges[j] = std::min(ranges[j], t(dirs[j]));
  }
  // The beams within the pseudo-angle interval [lo, hi] whose range so far is longer
  // than `nearest`.
  template <class Test>
  void beams_between(double lo, double hi, double nearest, Test&& t) const {
    for_beams_between(*order, lo, hi, [&](uint32_t j) {
      if (ranges[j] > nearest) ranges[j] = std::min(ranges[j], t(dirs[j]));
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
  if (d2 <= kNear * kNear) return scan.all_beams(test);
  // The wall's ends in the robot's frame, and the angle between them counter-clockwise:
  // less than pi, since the origin is not on the wall.
  const Point ar = scan.to_robot(a), er = scan.to_robot(w.e);
  double pa = pseudo_angle(ar), pb = pseudo_angle(ar + er);
  if (cross(ar, er) < 0) std::swap(pa, pb);
  if (pb < pa) pb += 4;
  // No hit on the wall is nearer than its nearest point, less the test's tolerance.
  scan.beams_between(pa - kAngleSlack, pb + kAngleSlack, std::sqrt(d2) - 2 * kRayTolerance, test);
}

// Stairs and ramps stop rays only inside their bounding box: the beams within the angle
// its circumscribed circle subtends (a pseudo-angle moves no faster than the angle).
void sweep_special(const Scan& scan, const SpecialObstacle& sp) {
  const Rect& b = sp.bounds;
  const Point v = Point{(b.xmin + b.xmax) / 2, (b.ymin + b.ymax) / 2} - scan.o;
  const double radius = std::hypot(b.xmax - b.xmin, b.ymax - b.ymin) / 2 + kRayTolerance;
  const double dist = norm(v);
  if (dist - radius > scan.reach) return;
  auto test = [&](Point d) { return sp.distance(scan.o, d); };
  if (dist <= radius + kNear) return scan.all_beams(test);
  const double pc = pseudo_angle(scan.to_robot(v)), half = std::asin(radius / dist) + kAngleSlack;
  scan.beams_between(pc - half, pc + half, dist - radius - 2 * kRayTolerance, test);
}

}  // namespace

SweepRayCaster::SweepRayCaster(const Map& map, RayCasterOptions options, SweepOptions sweep)
    : options_(options),
      obstacles_(prepare_laser_obstacles(map, options.laser_height)),
      candidates_(obstacles_, sweep.cell, options.rmax, sweep.max_bytes) {}

size_t SweepRayCaster::memory_bytes() const {
  return candidates_.memory_bytes() + obstacles_.walls.capacity() * sizeof(RaySegment) +
         obstacles_.specials.capacity() * sizeof(SpecialObstacle);
}

double SweepRayCaster::cast_direction(Point o, Point d) const {
  double best = options_.rmax;
  const uint32_t walls = candidates_.wall_count();
  for (const CandidateGrid::Candidate& c : candidates_.near(o)) {
    if (c.nearest >= best) break;  // nearest first: nothing further on can be nearer
    if (c.id >= walls) {
      best = std::min(best, obstacles_.specials[c.id - walls].distance(o, d));
      continue;
    }
    const RaySegment& w = obstacles_.walls[c.id];
    // Both ends (widened by the test's tolerance) on one side of the ray's line: no hit.
    const double sa = cross(d, w.a - o), sb = sa + cross(d, w.e);
    if ((sa > kSideSlack && sb > kSideSlack) || (sa < -kSideSlack && sb < -kSideSlack)) continue;
    best = std::min(best, ray_segment_distance(w, o, d));
  }
  return best;
}

void SweepRayCaster::cast_scan(Point o, double theta, const std::vector<double>& relative_angles,
                               double* ranges) const {
  const size_t n = relative_angles.size();
  std::fill(ranges, ranges + n, options_.rmax);  // the nearest hit so far, per beam
  const std::span<const CandidateGrid::Candidate> near = candidates_.near(o);
  if (near.empty() || n == 0) return;

  thread_local std::vector<Point> dirs;
  dirs.resize(n);
  scan_directions(theta, relative_angles, dirs.data());
  Scan scan;
  scan.o = o;
  scan.dirs = dirs.data();
  scan.order = &beam_order(relative_angles);
  scan.c = std::cos(theta);
  scan.s = std::sin(theta);
  scan.ranges = ranges;
  scan.n = n;
  scan.reach = options_.rmax + CandidateGrid::kPad;
  const uint32_t walls = candidates_.wall_count();
  for (const CandidateGrid::Candidate& c : near) {
    if (c.id < walls)
      sweep_wall(scan, obstacles_.walls[c.id]);
    else
      sweep_special(scan, obstacles_.specials[c.id - walls]);
  }
}

std::unique_ptr<RayCaster> make_fast_ray_caster(const Map& map, RayCasterOptions options) {
  const SweepOptions sweep;
  const LaserObstacles obstacles = prepare_laser_obstacles(map, options.laser_height);
  // The lists must fit with cells at most twice the default: larger cells would list
  // so many walls per scan that walking a grid is faster.
  if (CandidateGrid::estimate_bytes(obstacles, 2 * sweep.cell, options.rmax) > sweep.max_bytes)
    return std::make_unique<GridRayCaster>(map, options);
  return std::make_unique<SweepRayCaster>(map, options, sweep);
}

}  // namespace fleetmap
