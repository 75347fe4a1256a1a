#pragma once
// The fast RayCaster: a scan reads the candidate list of its origin's cell
// (common/raycast/candidate_grid.h: every wall, stair and ramp within rmax of the cell,
// less the walls a nearer wall hides from the whole cell) and sweeps it wall by wall:
// each wall is tested, with the shared exact test (common/raycast/ray_segment.h), only
// against the beams inside the angle it subtends from the origin, a run of consecutive
// beams tested in one vectorised loop (common/raycast/sweep_kernels.h). Stairs and ramps
// are judged as a whole (common/raycast/ray_rules.h).
//
// This is the seed's idea (seed 000 section 4.1: cull obstacles against the scanner's
// circle once per scan, then test the rest) with the culling precomputed per cell,
// occlusion included, and refined per beam. Results equal SeedRayCaster's: the same test
// on a superset of the walls that can be hit first
// (tests/common/raycast/ray_caster_equivalence_test.cpp; docs/ray-casting.md).
//
// Memory grows with rmax^2 times the walls' density; the cell size is doubled until
// the lists fit in SweepOptions::max_bytes. make_fast_ray_caster() picks GridRayCaster
// (grid_ray_caster.h, memory independent of rmax) when even that does not fit.
#include <cstddef>
#include <memory>

#include "common/raycast/candidate_grid.h"
#include "common/map/map.h"
#include "common/raycast/ray_caster.h"
#include "common/raycast/ray_rules.h"

namespace fleetmap {

// How a scan is swept over its list (common/raycast/sweep_kernels.h).
enum class SweepKernel { batched, per_beam };

struct SweepOptions {
  // Metres; 0 picks by density: kDenseCell where the kSparseCell lists would average
  // more than kDenseList entries (a building floor), else kSparseCell (a campus, where
  // small cells only cost memory and build time). bench-raycast compares sizes
  // (docs/ray-casting.md, "The sweep on dense floors").
  double cell = 0;
  static constexpr double kDenseCell = 0.5, kSparseCell = 4.0, kDenseList = 32;
  size_t max_bytes = 64u << 20;  // budget of the candidate lists
  SweepKernel kernel = SweepKernel::batched;
  // Walls of a cell's list tried as occluders of the farther ones (0: no culling). The
  // small cells of a dense floor hide more with more of them, at little build cost:
  // they are built from their parents' culled lists (candidate_grid.h).
  size_t occluders = 128;
};

class SweepRayCaster : public RayCaster {
 public:
  // Throws std::invalid_argument when a ramp's surface encoding is wrong.
  SweepRayCaster(const Map& map, RayCasterOptions options, SweepOptions sweep = {});

  double cast_direction(Point origin, Point dir) const override;
  void cast_scan(Point origin, double theta, const std::vector<double>& relative_angles, double* ranges) const override;
  const RayCasterOptions& options() const override { return options_; }

  size_t memory_bytes() const;
  const CandidateGrid& candidates() const { return candidates_; }

 private:
  RayCasterOptions options_;
  SweepKernel kernel_;
  LaserObstacles obstacles_;
  CandidateGrid candidates_;
};

// The fast caster for a map (what the robot uses): SweepRayCaster, or GridRayCaster
// when the candidate lists would not fit.
std::unique_ptr<RayCaster> make_fast_ray_caster(const Map& map, RayCasterOptions options);

}  // namespace fleetmap
