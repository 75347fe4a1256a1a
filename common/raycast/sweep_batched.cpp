// The batched sweep (sweep_kernels.h): the beams a wall covers are consecutive entries of
// structure-of-arrays beams, tested in one vectorisable loop.
//
// The loop computes what ray_segment_distance() computes for a ray that is not parallel
// to the wall, with the same operations in the same order (no contraction into FMA: the
// AVX2 clone does not enable it), so the ranges are the same bits. The cases that test
// decides apart (origin on the wall's line, a beam parallel to the wall) go through
// ray_segment_distance() itself. What the sweep needs of each wall before its runs (its
// interval of pseudo-angles, its runs of beams, how it is swept) is computed for four
// walls at a time (wall_lanes), again by the scalar code's operations in its order.
#include <algorithm>
#include <cmath>
#include <cstdint>

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

// Four walls at a time (GNU vector extensions, understood by g++ and clang; four
// doubles are an AVX2 register in that clone, two SSE2 ones otherwise).
using V4 = double __attribute__((vector_size(32)));
using V4i = int64_t __attribute__((vector_size(32)));

constexpr int64_t kBeyond = 1, kNearWall = 2, kExactWall = 4;  // wall_lanes() kind; 0: swept by hit_run()

[[gnu::always_inline]] inline void abs4(const V4& x, V4& out) {
  out = (V4)((V4i)x & INT64_MAX);  // std::fabs, bit for bit
}

// pseudo_angle() of four directions: the same operations. (Vectors go by reference:
// by value, clang refuses them in the clone without AVX, whose ABI passes them apart.)
[[gnu::always_inline]] inline void pseudo_angle4(const V4& x, const V4& y, V4& out) {
  V4 abs_x, abs_y;
  abs4(x, abs_x);
  abs4(y, abs_y);
  const V4 r = y / (abs_x + abs_y);
  const V4i left = x < 0, below = y < 0;
  const V4 zero = {}, base = left ? zero + 2.0 : (below ? zero + 4.0 : zero);
  const V4 sign = left ? zero - 1.0 : zero + 1.0;
  out = base + sign * r;
}

using V4si = int32_t __attribute__((vector_size(16)));

// BeamOrder::lower(x, strict) of four x, for an order with one_per_bin: the same bin
// (x clamped to [0, 4] first, which gives the same bins, and a NaN of a lane that is
// not used bin 0), then the one step.
template <bool strict>
[[gnu::always_inline]] inline void lower4(const BeamOrder& order, const V4& x, V4i& out) {
  const V4 zero = {};
  V4 xc = x >= 0 ? x : zero;
  xc = xc > 4 ? zero + 4.0 : xc;
  const V4si bin = __builtin_convertvector(xc * BeamOrder::kBinsPerUnit, V4si);
  const uint32_t* first = order.first.data();
  const V4i k = {first[bin[0]], first[bin[1]], first[bin[2]], first[bin[3]]};
  const int64_t n = static_cast<int64_t>(order.pseudo.size());
  const V4i inside = k < n;
  const V4i kc = inside ? k : k - 1;  // n > 0
  const double* pseudo = order.pseudo.data();
  const V4 p = {pseudo[kc[0]], pseudo[kc[1]], pseudo[kc[2]], pseudo[kc[3]]};
  const V4i below = strict ? p <= x : p < x;
  out = k - (inside & below);  // a mask is -1
}

// What the sweep needs of four walls seen from the origin o, by the same operations in
// the same order as the scalar sweep made them wall by wall (so the same bits): their
// WallView fields, their pseudo-angle intervals in the robot's frame (rotated by
// -theta: cos c, sin s) with the slack, and how each is swept (kind).
// With order.one_per_bin, also the runs of beams for_runs_between() would give: [k0, k1)
// and [0, kb).
[[gnu::always_inline]] inline void wall_lanes(const RaySegment* const* w, Point o, double c, double s, double reach2,
                                              const BeamOrder& order, double* wx, double* wy, double* num_t,
                                              double* lo, double* hi, int64_t* kind, int64_t* k0, int64_t* k1,
                                              int64_t* kb) {
  const V4 ax = V4{w[0]->a.x, w[1]->a.x, w[2]->a.x, w[3]->a.x} - o.x;  // a = the wall's start - o
  const V4 ay = V4{w[0]->a.y, w[1]->a.y, w[2]->a.y, w[3]->a.y} - o.y;
  const V4 ex = {w[0]->e.x, w[1]->e.x, w[2]->e.x, w[3]->e.x}, ey = {w[0]->e.y, w[1]->e.y, w[2]->e.y, w[3]->e.y};
  const V4 inv_len2 = {w[0]->inv_len2, w[1]->inv_len2, w[2]->inv_len2, w[3]->inv_len2};
  const V4 tol_cross = {w[0]->tol_cross, w[1]->tol_cross, w[2]->tol_cross, w[3]->tol_cross};
  const V4 zero = {};
  V4 uq = -(ax * ex + ay * ey) * inv_len2;
  uq = uq < 0 ? zero : (1 < uq ? zero + 1.0 : uq);  // std::clamp(uq, 0.0, 1.0)
  const V4 qx = ax + uq * ex, qy = ay + uq * ey;     // the wall's point nearest the origin
  const V4 d2 = qx * qx + qy * qy;
  const V4 cr = ax * ey - ay * ex;  // cross(a, e)
  // The wall's ends in the robot's frame, and the angle between them counter-clockwise:
  // less than pi, since the origin is not on the wall.
  const V4 arx = c * ax + s * ay, ary = c * ay - s * ax;
  const V4 erx = c * ex + s * ey, ery = c * ey - s * ex;
  const V4 brx = arx + erx, bry = ary + ery;
  V4 p0, p1;
  pseudo_angle4(arx, ary, p0);
  pseudo_angle4(brx, bry, p1);
  const V4i clockwise = arx * ery - ary * erx < 0;
  const V4 pa = clockwise ? p1 : p0;
  V4 pb = clockwise ? p0 : p1;
  pb += pb < pa ? zero + 4.0 : zero;
  // The origin near the wall's line (beyond its ends), where a beam may be parallel
  // to it or the test's on-the-line branch applies: ray_segment_distance() decides.
  const V4 bx = ax + ex, by = ay + ey;
  const V4 aa = ax * ax + ay * ay, bb = bx * bx + by * by;
  V4 abs_cr;
  abs4(cr, abs_cr);
  const V4i exact = (cr * cr * inv_len2 <= kSafeSine2 * (aa < bb ? bb : aa)) | (abs_cr <= tol_cross);
  const V4i nil = {};
  const V4i k = (d2 > reach2 ? nil + kBeyond : nil) | (d2 <= kSweepNear * kSweepNear ? nil + kNearWall : nil) |
                (exact ? nil + kExactWall : nil);
  const V4 l = pa - kSweepAngleSlack, h = pb + kSweepAngleSlack;
  __builtin_memcpy(wx, &ax, sizeof(V4));
  __builtin_memcpy(wy, &ay, sizeof(V4));
  __builtin_memcpy(num_t, &cr, sizeof(V4));
  __builtin_memcpy(lo, &l, sizeof(V4));
  __builtin_memcpy(hi, &h, sizeof(V4));
  __builtin_memcpy(kind, &k, sizeof(V4i));
  if (!order.one_per_bin) return;
  // for_runs_between(order, l, h): the whole circle, or [l + 4, 4] and [0, h] when l < 0,
  // or [l, 4] and [0, h - 4] when h >= 4 (lower(4, true) is n, lower(0, false) is 0).
  const V4i whole = h - l >= 4, wrap = (l < 0) | (h >= 4);
  const V4 lw = l < 0 ? l + 4 : l, hw = h >= 4 ? h - 4 : h;
  V4i from, to;
  lower4<false>(order, lw, from);
  lower4<true>(order, hw, to);
  const V4i none = {};
  const int64_t n = static_cast<int64_t>(order.pseudo.size());
  const V4i r0 = whole ? none : from, r1 = (whole | wrap) ? none + n : to, rb = whole ? none : (wrap ? to : none);
  __builtin_memcpy(k0, &r0, sizeof(V4i));
  __builtin_memcpy(k1, &r1, sizeof(V4i));
  __builtin_memcpy(kb, &rb, sizeof(V4i));
}

}  // namespace

__attribute__((target_clones("avx2", "default"))) void sweep_batched(const SweepScan& in,
                                                                      const std::vector<double>& relative_angles,
                                                                      double* ranges) {
  const size_t n = relative_angles.size();
  if (in.near.empty() || n == 0) {
    std::fill(ranges, ranges + n, in.rmax);
    return;
  }
  const BeamOrder& order = beam_order(relative_angles);
  thread_local Beams beams;
  const size_t n4 = (n + 3) / 4 * 4;  // the directions are rotated four at a time
  beams.dx.resize(n4);
  beams.dy.resize(n4);
  beams.r.assign(n, in.rmax);
  double* __restrict dx = beams.dx.data();
  double* __restrict dy = beams.dy.data();
  double* __restrict r = beams.r.data();
  // As scan_directions() rotates them: the same bits.
  const double c = std::cos(in.theta), s = std::sin(in.theta);
  for (size_t k = 0; k < n4; k += 4) {
    V4 ux, uy;
    __builtin_memcpy(&ux, order.unit_x.data() + k, sizeof(V4));
    __builtin_memcpy(&uy, order.unit_y.data() + k, sizeof(V4));
    const V4 x = c * ux - s * uy, y = s * ux + c * uy;
    __builtin_memcpy(dx + k, &x, sizeof(V4));
    __builtin_memcpy(dy + k, &y, sizeof(V4));
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
  // A special (stair, ramp), judged as a whole over the beams of its cone.
  auto special = [&](uint32_t id) {
    const SpecialObstacle& sp = in.obstacles->specials[id - in.walls];
    const SpecialCone cone = special_cone(sp, o);
    if (cone.dist - cone.radius > in.reach) return;
    auto test = [&](Point d) { return sp.distance(o, d); };
    if (cone.dist <= cone.radius + kSweepNear) {
      exact_run(0, n, test);
      return;
    }
    const double pc = pseudo_angle(to_robot(cone.centre)), half = cone.half_angle();
    for_runs_between(order, pc - half, pc + half, [&](size_t k0, size_t k1) { exact_run(k0, k1, test); });
  };
  // The candidates go by blocks: the early stop is checked before each block but the
  // first (before candidates 7, 15, 23, ...). In a block, (1) the candidates whose arc
  // meets the scan's are packed; (2) their walls' intervals from the origin are computed
  // four at a time in vectors; (3) the walls are swept one by one. Min is commutative:
  // the order in which a block's walls and specials shorten ranges changes no bit.
  constexpr size_t kLanes = 8;
  alignas(32) uint32_t id[kLanes] = {};  // lanes past the packed walls name some wall, ignored
  alignas(32) double wx[kLanes], wy[kLanes], num_t[kLanes], lo[kLanes], hi[kLanes];
  alignas(32) int64_t kind[kLanes], k0[kLanes], k1[kLanes], kb[kLanes];
  const bool lanes_runs = order.one_per_bin;
  const CandidateGrid::Candidate* const cands = in.near.data();
  const size_t count = in.near.size();
  for (size_t begin = 0, end = std::min<size_t>(kLanes - 1, count); begin < count;
       begin = end, end = std::min(count, end + kLanes)) {
    // Nearest first: once no beam is longer than this candidate's distance from the
    // cell, nothing further on can shorten one.
    if (begin > 0 && !any_longer(r, n, cands[begin].nearest)) break;
    size_t m = 0;
    for (size_t i = begin; i < end; ++i) {
      const CandidateGrid::Candidate& cand = cands[i];
      // The candidate's arc from the cell (candidate_grid.h) misses the scan's: no beam
      // comes near it.
      bool pass = true;
      if (!all_around) {
        double d1 = cand.arc_lo - arc_start, d2 = -d1;
        d1 += d1 < 0 ? 4 : 0;
        d2 += d2 < 0 ? 4 : 0;
        pass = (d1 <= arc_width) | (d2 <= cand.arc_width);
      }
      if (cand.id >= in.walls) {
        if (pass) special(cand.id);
        continue;
      }
      id[m] = cand.id;
      m += pass ? 1 : 0;
    }
    if (m == 0) continue;
    for (size_t g = 0; g < m; g += 4) {
      const RaySegment* const four[4] = {&walls[id[g]], &walls[id[g + 1]], &walls[id[g + 2]], &walls[id[g + 3]]};
      wall_lanes(four, o, c, s, reach2, order, wx + g, wy + g, num_t + g, lo + g, hi + g, kind + g, k0 + g, k1 + g,
                 kb + g);
    }
    for (size_t j = 0; j < m; ++j) {
      if (kind[j] & kBeyond) continue;  // every hit would be past rmax
      const RaySegment& seg = walls[id[j]];
      if (kind[j] != 0) {
        auto test = [&](Point d) { return ray_segment_distance(seg, o, d); };
        if (kind[j] & kNearWall)
          exact_run(0, n, test);
        else
          for_runs_between(order, lo[j], hi[j], [&](size_t k0, size_t k1) { exact_run(k0, k1, test); });
        continue;
      }
      const WallView w{wx[j], wy[j], seg.e.x, seg.e.y, num_t[j], -seg.tol_u, 1 + seg.tol_u};
      if (lanes_runs) {
        if (k0[j] < k1[j]) hit_run(dx, dy, r, k0[j], k1[j], w);
        if (kb[j] > 0) hit_run(dx, dy, r, 0, kb[j], w);
        continue;
      }
      for_runs_between(order, lo[j], hi[j], [&](size_t from, size_t to) __attribute__((always_inline)) {
        hit_run(dx, dy, r, from, to, w);
      });
    }
  }
  if (order.rotated) {  // two copies
    const size_t off = order.rotation;
    std::copy(r, r + (n - off), ranges + off);
    std::copy(r + (n - off), r + n, ranges);
    return;
  }
  for (size_t k = 0; k < n; ++k) ranges[order.beam[k]] = r[k];
}

}  // namespace fleetmap
