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

  double cell() const { return cell_; }
  double inv_cell() const { return inv_cell_; }
  Point corner() const { return corner_; }  // lower-left corner of cell (0, 0)
  int nx() const { return nx_; }
  int ny() const { return ny_; }
  Rect rect() const { return {corner_.x, corner_.y, corner_.x + nx_ * cell_, corner_.y + ny_ * cell_}; }
  bool empty() const { return nx_ == 0; }

  const Cell& at(int ix, int iy) const { return cells_[static_cast<size_t>(iy) * nx_ + ix]; }
  const RaySegment* walls() const { return walls_.data(); }
  const uint32_t* special_lists() const { return special_lists_.data(); }

  size_t memory_bytes() const;
  size_t wall_entries() const { return walls_.size(); }

 private:
  double cell_, inv_cell_;
  Point corner_;
  int nx_ = 0, ny_ = 0;
  std::vector<Cell> cells_;
  std::vector<RaySegment> walls_;
  std::vector<uint32_t> special_lists_;
};

}  // namespace fleetmap
