#pragma once
// A uniform grid over the obstacles that can stop a laser (common/raycast/ray_rules.h), built for
// walking rays through it (GridRayCaster). Each cell lists
//   * the wall segments that come within kCellPad of it, copied inline so that a ray
//     reads one cell's walls from one contiguous block;
//   * the stairs and ramps (judged as a whole) whose bounding box comes that close;
//   * skip: a distance no point of the cell is nearer than to any listed geometry of
//     any cell, so that a ray in an empty cell may jump that far at once. It is capped,
//     which keeps the build linear in the number of segments.
// Listing every segment near a cell, not only those through it, makes the walk immune
// to the rounding of cell boundaries: a ray never misses a segment by stepping into
// the neighbouring cell a hair early or late.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "common/geometry/grid_frame.h"
#include "common/raycast/ray_rules.h"

namespace fleetmap {

class SegmentGrid {
 public:
  struct Cell {
    uint32_t walls_begin = 0, walls_end = 0;  // into walls()
    float skip = 0;                           // metres; 0 next to anything
    uint32_t specials = 0;                    // into special_lists(): count, then ids; 0 = none
  };
  static constexpr double kCellPad = 1e-6;  // metres

  // cell: side in metres; skip_cap: largest skip stored (metres).
  SegmentGrid(const LaserObstacles& obstacles, double cell, double skip_cap);

  const GridFrame& frame() const { return frame_; }
  double cell() const { return frame_.cell; }
  double inv_cell() const { return inv_cell_; }  // for walking rays: a product per step, not a quotient
  Point corner() const { return frame_.origin; }  // lower-left corner of cell (0, 0)
  int nx() const { return frame_.width; }
  int ny() const { return frame_.height; }
  Rect rect() const { return frame_.rect(); }
  bool empty() const { return frame_.width == 0; }

  const Cell& at(int ix, int iy) const { return cells_[frame_.index(ix, iy)]; }
  const RaySegment* walls() const { return walls_.data(); }
  const uint32_t* special_lists() const { return special_lists_.data(); }

  size_t memory_bytes() const;
  size_t wall_entries() const { return walls_.size(); }

 private:
  GridFrame frame_;
  double inv_cell_;
  std::vector<Cell> cells_;
  std::vector<RaySegment> walls_;
  std::vector<uint32_t> special_lists_;
};

}  // namespace fleetmap
