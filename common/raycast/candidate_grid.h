#pragma once
// For each cell of a uniform grid, every obstacle that can stop a laser ray of length
// rmax cast from anywhere in the cell (its "potentially visible set"): the walls whose
// distance to the cell is at most rmax, and the stairs and ramps whose bounding box is;
// optionally less the walls another wall of the list hides from the whole cell
// (occlusion.h), which can never end a ray first. One list read per scan replaces a walk through many cells per ray, which is what
// costs on random poses: the list is one or two cache lines, the walls it names are a
// small array that stays in cache.
//
// Ids below wall_count() index LaserObstacles::walls; the others, minus wall_count(),
// index LaserObstacles::specials. Each list is ordered nearest first, with a distance
// no point of the cell is nearer than: a single ray stops reading the list once that
// passes its nearest hit, and a scan meets the walls that end most rays first.
//
// With culling, cells finer than kRootCell are built level by level, each cell from its
// parent's culled list (a wall hidden from the parent is hidden from each quarter of
// it): small cells cost their parents' short lists, not every wall within reach, so
// more occluders are affordable there (docs/ray-casting.md, "The sweep on dense floors").
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "common/geometry/grid_frame.h"
#include "common/raycast/ray_rules.h"

namespace fleetmap {

class CandidateGrid {
 public:
  static constexpr double kPad = 1e-6;  // metres added to rmax: immune to rounding
  // With culling, cells finer than this are built by halving cells of about this size.
  static constexpr double kRootCell = 4.0;  // metres

  struct Candidate {
    uint32_t id;
    float nearest;  // metres: no point of the cell is nearer to it (rounded down)
    // Every direction from the cell to it lies in the pseudo-angle arc (beam_order.h)
    // [arc_lo, arc_lo + arc_width] modulo 4, widened beyond the sweep's slack; a width
    // of 4 (stairs, ramps, walls touching the cell) is every direction.
    float arc_lo;
    float arc_width;
  };

  // cell: side in metres, doubled until the lists are known to fit in max_bytes.
  // occluders > 0: each list leaves out the walls that one of its `occluders` nearest
  // kept walls hides from the whole cell (occlusion.h); 0 keeps every wall within reach.
  CandidateGrid(const LaserObstacles& obstacles, double cell, double rmax, size_t max_bytes, size_t occluders = 0);

  // The candidates for a ray from p (empty outside the grid: nothing is within rmax).
  std::span<const Candidate> near(Point p) const {
    const std::optional<size_t> c = frame_.index_of(p);
    if (!c) return {};
    return {list_.data() + offsets_[*c], list_.data() + offsets_[*c + 1]};
  }

  uint32_t wall_count() const { return wall_count_; }
  double cell() const { return frame_.cell; }
  size_t cells() const { return frame_.cells(); }
  size_t entries() const { return list_.size(); }
  size_t memory_bytes() const;
  // Bytes the lists would take with this cell size (what the constructor checks).
  static size_t estimate_bytes(const LaserObstacles& obstacles, double cell, double rmax);
  // The entries per cell that estimate implies (an upper bound of the mean list).
  static double estimate_mean_list(const LaserObstacles& obstacles, double cell, double rmax);

 private:
  class CellCuller;  // one cell's list from its sorted obstacles (candidate_grid.cpp)

  std::span<const Candidate> near_cell(size_t c) const {
    return {list_.data() + offsets_[c], list_.data() + offsets_[c + 1]};
  }
  // Every obstacle within reach of each cell, culled (a grid of `cell`).
  void build_root(const LaserObstacles& obstacles, double cell, double reach, CellCuller& culler);
  // Cells of half the size, each from its parent's list.
  void halve(const LaserObstacles& obstacles, double reach, CellCuller& culler);

  GridFrame frame_;
  uint32_t wall_count_ = 0;
  std::vector<uint32_t> offsets_;  // cells() + 1
  std::vector<Candidate> list_;
};

}  // namespace fleetmap
