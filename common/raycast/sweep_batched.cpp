// The batched sweep (sweep_kernels.h): the beams a wall covers are consecutive entries of
// structure-of-arrays beams, tested in one vectorisable loop.
//
// The loop computes what ray_segment_distance() computes for a ray that is not parallel
// to the wall, with the same operations in the same order (no contraction into FMA: the
// AVX2 clone does not enable it), so the ranges are the same bits. The cases that test
// decides apart (origin on the wall's line, a beam parallel to the wall) go through
// ray_segment_distance() itself.
#include <algorithm>
#include <cmath>

#include "common/raycast/beam_order.h"
#include "common/raycast/sweep_constants.h"
#include "common/raycast/sweep_kernels.h"

namespace fleetmap {
namespace {

// The scan's beams in the order of BeamOrder: directions in the world frame and the
// nearest hit so far.
struct Beams {
  std::vector<double> dx, dy, r;
};

// A wall seen from the origin, as the general branch of ray_segment_distance() uses it.
struct WallView {
  double wx, wy;  // a - o
  double ex, ey;  // b - a
  double num_t;   // cross(a - o, e)
  double lo_u, hi_u;
};

// A beam of a wall's run makes an angle with the wall's line of at least the angle its
// nearer-to-parallel end makes, less the run's slack (kSweepAngleSlack in pseudo-angle,
// at most 2e-5 rad). Past 1e-4 rad for both ends, no beam of the run comes near the
// exact test's parallel threshold (1e-12 rad): sin(angle at an end) = |num_t| / (|e| |end|).
constexpr double kSafeSine2 = 1e-8;

// Ranges [k0, k1) against the wall, for a wall no beam of the run is parallel to.
[[gnu::always_inline]] inline void hit_run(const double* __restrict dx, const double* __restrict dy,
                                           double* __restrict r, size_t k0, size_t k1, const WallView& w) {
  const double wx = w.wx, wy = w.wy, ex = w.ex, ey = w.ey, num_t = w.num_t;
  const double lo_u = w.lo_u, hi_u = w.hi_u;
  // The beams' arrays do not alias (__restrict); g++ is told so once more. (clang's
  // vectorize(enable) would warn, an error under -Werror, wherever it cannot vectorise.)
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC ivdep
#endif
  for (size_t k = k0; k < k1; ++k) {
    const double x = dx[k], y = dy[k], rk = r[k];
    const double denom = x * ey - y * ex;  // cross(d, e)
    const double inv = 1 / denom;
    const double t = num_t * inv;
    const double u = (wx * y - wy * x) * inv;  // cross(w, d) / denom
    const bool hit = (t >= 0) & (u >= lo_u) & (u <= hi_u) & (t < rk);
    r[k] = hit ? t : rk;
  }
}

// Whether some beam's range is longer than x.
[[gnu::always_inline]] inline bool any_longer(const double* __restrict r, size_t n, double x) {
  long any = 0;
  for (size_t k = 0; k < n; ++k) any |= static_cast<long>(r[k] > x);
  return any != 0;
}

}  // namespace

__attribute__((target_clones("avx2", "default"))) void sweep_batched(const SweepScan& in,
                                                                      const std::vector<double>& relative_angles,
                                                                      double* ranges) {
  const size_t n = relative_angles.size();
  std::fill(ranges, ranges + n, in.rmax);
  if (in.near.empty() || n == 0) return;
  const BeamOrder& order = beam_order(relative_angles);
  thread_local Beams beams;
  beams.dx.resize(n);
  beams.dy.resize(n);
  beams.r.assign(n, in.rmax);
  double* __restrict dx = beams.dx.data();
  double* __restrict dy = beams.dy.data();
  double* __restrict r = beams.r.data();
  // As scan_directions() rotates them: the same bits.
  const double c = std::cos(in.theta), s = std::sin(in.theta);
  for (size_t k = 0; k < n; ++k) {
    const Point u = order.unit[k];
    dx[k] = c * u.x - s * u.y;
    dy[k] = s * u.x + c * u.y;
  }
  const Point o = in.origin;
  auto to_robot = [&](Point v) { return Point{c * v.x + s * v.y, c * v.y - s * v.x}; };  // rotation by -theta
  // Exact test, beam by beam, over a run.
  auto exact_run = [&](size_t k0, size_t k1, auto&& test) {
    for (size_t k = k0; k < k1; ++k) r[k] = std::min(r[k], test(Point{dx[k], dy[k]}));
  };
  // The scan's arc in the world frame: the pseudo-angle is monotonic in the angle, so
  // the rotated arc runs from the first beam's world pseudo-angle to the last's.
  const bool all_around = order.all_around;
  const double arc_start = all_around ? 0 : pseudo_angle({dx[order.arc_first], dy[order.arc_first]});
  double arc_width = all_around ? 4 : pseudo_angle({dx[order.arc_last], dy[order.arc_last]}) - arc_start;
  if (arc_width < 0) arc_width += 4;
  const double reach2 = in.reach * in.reach;
  const std::vector<RaySegment>& walls = in.obstacles->walls;
  size_t since_check = 0;
  for (const CandidateGrid::Candidate& cand : in.near) {
    // Nearest first: once no beam is longer than this candidate's distance from the
    // cell, nothing further on can shorten one. Checked every few candidates.
    if (++since_check == 8) {
      since_check = 0;
      if (!any_longer(r, n, cand.nearest)) break;
    }
    // The candidate's arc from the cell (candidate_grid.h) misses the scan's: no beam
    // comes near it.
    if (!all_around) {
      double d1 = cand.arc_lo - arc_start, d2 = -d1;
      d1 += d1 < 0 ? 4 : 0;
      d2 += d2 < 0 ? 4 : 0;
      if (!(d1 <= arc_width || d2 <= cand.arc_width)) continue;
    }
    if (cand.id >= in.walls) {
      const SpecialObstacle& sp = in.obstacles->specials[cand.id - in.walls];
      const SpecialCone cone = special_cone(sp, o);
      if (cone.dist - cone.radius > in.reach) continue;
      auto test = [&](Point d) { return sp.distance(o, d); };
      if (cone.dist <= cone.radius + kSweepNear) {
        exact_run(0, n, test);
        continue;
      }
      const double pc = pseudo_angle(to_robot(cone.centre)), half = cone.half_angle();
      for_runs_between(order, pc - half, pc + half, [&](size_t k0, size_t k1) { exact_run(k0, k1, test); });
      continue;
    }
    const RaySegment& seg = walls[cand.id];
    const Point a = seg.a - o;
    const double uq = std::clamp(-dot(a, seg.e) * seg.inv_len2, 0.0, 1.0);
    const Point q = a + uq * seg.e;  // the wall's point nearest the origin
    const double d2 = dot(q, q);
    if (d2 > reach2) continue;  // every hit would be past rmax
    auto test = [&](Point d) { return ray_segment_distance(seg, o, d); };
    const WallView w{a.x, a.y, seg.e.x, seg.e.y, cross(a, seg.e), -seg.tol_u, 1 + seg.tol_u};
    if (d2 <= kSweepNear * kSweepNear) {
      exact_run(0, n, test);
      continue;
    }
    // The wall's ends in the robot's frame, and the angle between them counter-clockwise:
    // less than pi, since the origin is not on the wall.
    const Point ar = to_robot(a), er = to_robot(seg.e);
    const double p0 = pseudo_angle(ar), p1 = pseudo_angle(ar + er);
    const bool clockwise = cross(ar, er) < 0;
    const double pa = clockwise ? p1 : p0;
    double pb = clockwise ? p0 : p1;
    pb += pb < pa ? 4.0 : 0.0;
    // The origin near the wall's line (beyond its ends), where a beam may be parallel
    // to it or the test's on-the-line branch applies: ray_segment_distance() decides.
    const Point b = a + seg.e;
    const bool exact = w.num_t * w.num_t * seg.inv_len2 <= kSafeSine2 * std::max(dot(a, a), dot(b, b)) ||
                       std::fabs(w.num_t) <= seg.tol_cross;
    for_runs_between(order, pa - kSweepAngleSlack, pb + kSweepAngleSlack, [&](size_t k0, size_t k1) __attribute__((always_inline)) {
      if (exact)
        exact_run(k0, k1, test);
      else
        hit_run(dx, dy, r, k0, k1, w);
    });
  }
  for (size_t k = 0; k < n; ++k) ranges[order.beam[k]] = r[k];
}

}  // namespace fleetmap
