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
#include <span>

#include "common/raycast/beam_order.h"
#include "common/raycast/sweep_constants.h"
#include "common/raycast/sweep_kernels.h"

namespace fleetmap {
namespace {

// The scan's beams in the order of BeamOrder: directions in the world frame and the
// nearest hit so far.
struct Beams {
  std::vector<double> dx, dy, r;
  std::vector<double> pos;  // pos[k] = k: the lanes' positions, for hit_run's mask
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

// Beams are tested in aligned blocks of kLanes, one vector each: a run of a few beams
// costs one or two blocks instead of a vector loop and a scalar remainder, whose trip
// counts vary from wall to wall and defeat branch prediction. The arrays are padded
// to whole blocks; a lane outside [k0, k1) keeps its range.
constexpr size_t kLanes = 4;

// Ranges [k0, k1) against the wall, for a wall no beam of the run is parallel to.
[[gnu::always_inline]] inline void hit_run(const double* __restrict dx, const double* __restrict dy,
                                           const double* __restrict pos, double* __restrict r, size_t k0,
                                           size_t k1, const WallView& w) {
  const double wx = w.wx, wy = w.wy, ex = w.ex, ey = w.ey, num_t = w.num_t;
  const double lo_u = w.lo_u, hi_u = w.hi_u;
  const double first = static_cast<double>(k0), last = static_cast<double>(k1);
  for (size_t kb = k0 & ~(kLanes - 1); kb < k1; kb += kLanes) {
    double out[kLanes];
    for (size_t j = 0; j < kLanes; ++j) {
      const size_t k = kb + j;
      const double x = dx[k], y = dy[k], rk = r[k];
      const double denom = x * ey - y * ex;  // cross(d, e)
      const double inv = 1 / denom;
      const double t = num_t * inv;
      const double u = (wx * y - wy * x) * inv;  // cross(w, d) / denom
      const bool hit = (pos[k] >= first) & (pos[k] < last) & (t >= 0) & (u >= lo_u) & (u <= hi_u) & (t < rk);
      out[j] = hit ? t : rk;
    }
    for (size_t j = 0; j < kLanes; ++j) r[kb + j] = out[j];
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
  const size_t padded = (n + kLanes - 1) / kLanes * kLanes;
  beams.dx.resize(padded);
  beams.dy.resize(padded);
  beams.r.assign(padded, in.rmax);
  if (beams.pos.size() < padded) {
    beams.pos.resize(padded);
    for (size_t k = 0; k < padded; ++k) beams.pos[k] = static_cast<double>(k);
  }
  double* __restrict dx = beams.dx.data();
  double* __restrict dy = beams.dy.data();
  double* __restrict r = beams.r.data();
  const double* __restrict pos = beams.pos.data();
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
  const double reach2 = in.reach * in.reach;
  const std::vector<RaySegment>& walls = in.obstacles->walls;

  // Sweeps one list over the beams of `pieces` (positions [k0, k1), at most two), whose
  // world pseudo-angles lie in [arc_start, arc_start + arc_width] modulo 4 (every
  // direction when all_around).
  struct Piece {
    size_t k0, k1;
  };
  // (Inlined: a lambda of its own would miss the AVX2 clone's target.)
  auto sweep_list = [&](std::span<const CandidateGrid::Candidate> list, const Piece* pieces, int count,
                        double arc_start, double arc_width, bool all_around) __attribute__((always_inline)) {
    // A run of positions cut to the pieces.
    auto clip = [&](size_t k0, size_t k1, auto&& run) __attribute__((always_inline)) {
      for (int i = 0; i < count; ++i) {
        const size_t a = std::max(k0, pieces[i].k0), b = std::min(k1, pieces[i].k1);
        if (a < b) run(a, b);
      }
    };
    auto longer = [&](double x) {
      bool any = false;
      for (int i = 0; i < count; ++i) any |= any_longer(r + pieces[i].k0, pieces[i].k1 - pieces[i].k0, x);
      return any;
    };
    size_t since_check = 0;
    for (const CandidateGrid::Candidate& cand : list) {
      // Nearest first: once no beam is longer than this candidate's distance from the
      // cell, nothing further on can shorten one. Checked every few candidates.
      if (++since_check == 4) {
        since_check = 0;
        if (!longer(cand.nearest())) break;
      }
      // The candidate's arc from the cell (candidate_grid.h) misses the beams': no beam
      // comes near it.
      if (!all_around) {
        double d1 = cand.arc_lo() - arc_start, d2 = -d1;
        d1 += d1 < 0 ? 4 : 0;
        d2 += d2 < 0 ? 4 : 0;
        if (!(d1 <= arc_width || d2 <= cand.arc_width())) continue;
      }
      if (cand.id >= in.walls) {
        const SpecialObstacle& sp = in.obstacles->specials[cand.id - in.walls];
        const SpecialCone cone = special_cone(sp, o);
        if (cone.dist - cone.radius > in.reach) continue;
        auto test = [&](Point d) { return sp.distance(o, d); };
        auto run = [&](size_t k0, size_t k1) { exact_run(k0, k1, test); };
        if (cone.dist <= cone.radius + kSweepNear) {
          clip(0, n, run);
          continue;
        }
        const double pc = pseudo_angle(to_robot(cone.centre)), half = cone.half_angle();
        for_runs_between(order, pc - half, pc + half, [&](size_t k0, size_t k1) { clip(k0, k1, run); });
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
        clip(0, n, [&](size_t k0, size_t k1) { exact_run(k0, k1, test); });
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
      for_runs_between(order, pa - kSweepAngleSlack, pb + kSweepAngleSlack,
                       [&](size_t k0, size_t k1) __attribute__((always_inline)) {
                         clip(k0, k1, [&](size_t a0, size_t a1) __attribute__((always_inline)) {
                           if (exact)
                             exact_run(a0, a1, test);
                           else
                             hit_run(dx, dy, pos, r, a0, a1, w);
                         });
                       });
    }
  };

  // The groups of beams swept apart, each over its own list.
  struct Group {
    int sector;
    Piece pieces[2];
    int count;
    double lo, hi;  // the beams' world pseudo-angles lie in [lo, hi] modulo 4
    bool all_around;
  };
  thread_local std::vector<Group> groups;
  groups.clear();
  const int sectors = in.grid && in.cell ? in.grid->sectors() : 1;
  {
    // The scan's arc in the world frame: the pseudo-angle is monotonic in the angle, so
    // the rotated arc runs from the first beam's world pseudo-angle to the last's.
    const bool all_around = order.all_around;
    const double arc_start = all_around ? 0 : pseudo_angle({dx[order.arc_first], dy[order.arc_first]});
    double arc_width = all_around ? 4 : pseudo_angle({dx[order.arc_last], dy[order.arc_last]}) - arc_start;
    if (arc_width < 0) arc_width += 4;
    // The whole list or, with sectors, the wide one first: its walls are the nearest
    // and end most beams, so the sectors stop sooner.
    groups.push_back({sectors == 1 ? 0 : sectors, {{0, n}, {0, 0}}, 1, arc_start, arc_start + arc_width, all_around});
  }
  if (sectors > 1) {
    // The beams by sector of their world direction: the positions of a sector are
    // consecutive (the world order of the beams is their robot-frame order turned), but
    // a group is made of each maximal run of one sector, so that rounding could only
    // split a sector's sweep in two, never skip a beam. The runs at both ends of the
    // order are one group when they share a sector (the order wraps there). Within a
    // sector, pseudo-angles do not wrap.
    for (size_t k = 0; k < n; ++k) {
      const double p = pseudo_angle({dx[k], dy[k]});
      const int sec = CandidateGrid::sector_of(p, sectors);
      if (k > 0 && groups.back().sector == sec) {
        Group& g = groups.back();
        g.pieces[0].k1 = k + 1;
        g.lo = std::min(g.lo, p);
        g.hi = std::max(g.hi, p);
      } else {
        groups.push_back({sec, {{k, k + 1}, {0, 0}}, 1, p, p, false});
      }
    }
    if (groups.size() > 2 && groups.back().sector == groups[1].sector) {
      Group& g = groups[1];
      const Group& last = groups.back();
      g.pieces[1] = last.pieces[0];
      g.count = 2;
      g.lo = std::min(g.lo, last.lo);
      g.hi = std::max(g.hi, last.hi);
      groups.pop_back();
    }
  }
  for (const Group& g : groups)
    sweep_list(in.cell ? in.grid->list(*in.cell, g.sector) : in.near, g.pieces, g.count, g.lo, g.hi - g.lo,
               g.all_around);
  for (size_t k = 0; k < n; ++k) ranges[order.beam[k]] = r[k];
}

}  // namespace fleetmap
