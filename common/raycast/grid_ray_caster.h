#pragma once
// A RayCaster whose rays walk a SegmentGrid (common/raycast/segment_grid.h) cell by cell in the
// order they cross them (Amanatides & Woo), test the walls listed in each cell with the
// shared exact test (common/raycast/ray_segment.h), and jump across empty space by each empty
// cell's skip distance. A walk ends when the nearest hit so far lies within the cell
// just tested, or at rmax. Stairs and ramps are judged as a whole (common/raycast/ray_rules.h)
// when the walk first meets a cell that lists them.
//
// Its memory does not depend on rmax, but on random poses each ray touches cells of
// its own, which costs more than SweepRayCaster's one list per scan (bench-raycast
// --alternatives): it is make_fast_ray_caster()'s fallback when those lists would not
// fit. Results equal SeedRayCaster's (tests/common/raycast/ray_caster_equivalence_test.cpp).
#include <cstddef>

#include "common/map/map.h"
#include "common/raycast/ray_caster.h"
#include "common/raycast/ray_rules.h"
#include "common/raycast/segment_grid.h"

namespace fleetmap {

struct GridOptions {
  double cell = 1.0;       // metres (bench-raycast compares sizes)
  bool skip_empty = true;  // false: plain cell-by-cell walk (the baseline)
};

class GridRayCaster : public RayCaster {
 public:
  // Throws std::invalid_argument when a ramp's surface encoding is wrong.
  GridRayCaster(const Map& map, RayCasterOptions options, GridOptions grid = {});

  double cast_direction(Point origin, Point dir) const override;
  const RayCasterOptions& options() const override { return options_; }

  size_t memory_bytes() const;  // the grid and the stairs and ramps it refers to
  const SegmentGrid& grid() const { return grid_; }

 private:
  RayCasterOptions options_;
  GridOptions grid_options_;
  LaserObstacles obstacles_;  // for the stairs and ramps; walls live in the grid
  SegmentGrid grid_;
};

}  // namespace fleetmap
