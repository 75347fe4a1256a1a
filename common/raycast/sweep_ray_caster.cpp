#include "common/raycast/sweep_ray_caster.h"

#include <algorithm>
#include <cmath>

#include "common/raycast/beam_order.h"
#include "common/raycast/grid_ray_caster.h"
#include "common/raycast/sweep_kernels.h"

namespace fleetmap {
namespace {

// A wall whose ends are farther than this from a ray's line, both on the same side,
// cannot be hit: the exact test widens a wall's ends by kRayTolerance only.
constexpr double kSideSlack = 4 * kRayTolerance;

constexpr double kLargestCell = 8.0;  // metres

double cell_for(const LaserObstacles& obstacles, const SweepOptions& sweep, double rmax) {
  if (sweep.cell > 0) return sweep.cell;
  return CandidateGrid::estimate_mean_list(obstacles, SweepOptions::kSparseCell, rmax) > SweepOptions::kDenseList
             ? SweepOptions::kDenseCell
             : SweepOptions::kSparseCell;
}

}  // namespace

SweepRayCaster::SweepRayCaster(const Map& map, RayCasterOptions options, SweepOptions sweep)
    : options_(options),
      kernel_(sweep.kernel),
      obstacles_(prepare_laser_obstacles(map, options.laser_height)),
      candidates_(obstacles_, cell_for(obstacles_, sweep, options.rmax), options.rmax, sweep.max_bytes,
                  sweep.occluders) {}

size_t SweepRayCaster::memory_bytes() const {
  return candidates_.memory_bytes() + obstacles_.walls.capacity() * sizeof(RaySegment) +
         obstacles_.specials.capacity() * sizeof(SpecialObstacle);
}

double SweepRayCaster::cast_direction(Point o, Point d) const {
  double best = options_.rmax;
  const uint32_t walls = candidates_.wall_count();
  const double pd = pseudo_angle(d);
  for (const CandidateGrid::Candidate& c : candidates_.near(o)) {
    if (c.nearest >= best) break;  // nearest first: nothing further on can be nearer
    // The ray's direction outside the arc of directions from the cell to it: no hit.
    double off = pd - c.arc_lo;
    off += off < 0 ? 4 : 0;
    if (off > c.arc_width) continue;
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
  SweepScan scan;
  scan.obstacles = &obstacles_;
  scan.near = candidates_.near(o);
  scan.walls = candidates_.wall_count();
  scan.origin = o;
  scan.theta = theta;
  scan.rmax = options_.rmax;
  scan.reach = options_.rmax + CandidateGrid::kPad;
  if (kernel_ == SweepKernel::per_beam)
    sweep_per_beam(scan, relative_angles, ranges);
  else
    sweep_batched(scan, relative_angles, ranges);
}

std::unique_ptr<RayCaster> make_fast_ray_caster(const Map& map, RayCasterOptions options) {
  const SweepOptions sweep;
  const LaserObstacles obstacles = prepare_laser_obstacles(map, options.laser_height);
  // The lists must fit with cells of at most kLargestCell: larger cells would list so
  // many walls per scan that walking a grid is faster.
  if (CandidateGrid::estimate_bytes(obstacles, kLargestCell, options.rmax) > sweep.max_bytes)
    return std::make_unique<GridRayCaster>(map, options);
  return std::make_unique<SweepRayCaster>(map, options, sweep);
}

}  // namespace fleetmap
