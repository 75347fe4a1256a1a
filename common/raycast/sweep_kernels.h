#pragma once
// The two ways SweepRayCaster (sweep_ray_caster.h) sweeps one scan over its origin's
// candidate list; both give the same ranges, bit for bit, as every caster does through
// the shared exact test (ray_segment.h).
//
//   per_beam  each wall is tested against the beams inside the angle it covers, one
//             beam at a time through the beam order, where the range so far is longer
//             than the wall's distance (the first sweep, kept for comparison).
//   batched   the beams are held by angle in arrays (direction x, direction y, range),
//             so the beams a wall covers are a run of consecutive entries, tested in a
//             loop the compiler vectorises (AVX2 where the processor has it, SSE2
//             otherwise); the sweep stops once no beam's range is longer than the next
//             candidate's distance (the list is nearest first). The list goes by blocks
//             of 8 candidates: the walls that pass the arc test are packed, and their
//             intervals and runs of beams computed four walls at a time.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "common/raycast/candidate_grid.h"
#include "common/raycast/ray_rules.h"

namespace fleetmap {

struct SweepScan {
  const LaserObstacles* obstacles = nullptr;
  std::span<const CandidateGrid::Candidate> near;  // the origin's list, nearest first
  uint32_t walls = 0;                              // ids below are walls, the others specials
  Point origin;
  double theta = 0;
  double rmax = 0;
  double reach = 0;  // rmax and a hair: nothing farther can shorten a range
};

// ranges[i] for the beam at theta + relative_angles[i], from rmax down to the nearest hit.
void sweep_per_beam(const SweepScan& scan, const std::vector<double>& relative_angles, double* ranges);
void sweep_batched(const SweepScan& scan, const std::vector<double>& relative_angles, double* ranges);

}  // namespace fleetmap
