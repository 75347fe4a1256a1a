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
// Each cell's list may be split by direction into `sectors` equal pseudo-angle sectors
// (beam_order.h) and a wide list: a candidate whose arc from the cell is wider than a
// sector is in the wide list, any other in each sector s its arc meets
// ([4 s / S, 4 (s + 1) / S]). A ray reads the wide list and its direction's sector; a
// scan reads the wide list with all its beams, then each sector its beams fall in with
// those beams only, so that a sector whose beams all stopped near stops reading (one
// corridor no longer keeps the whole scan reading far walls).
#include <algorithm>
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

  // 8 bytes, in fixed point: a scan reads its lists from memory (random poses leave
  // little in cache), so their size is much of a scan's time.
  struct Candidate {
    static constexpr double kNearUnit = 1.0 / 1024;  // metres
    static constexpr double kArcUnit = 1.0 / 16384;  // pseudo-angle
    static constexpr uint16_t kAllAround = 0xffff;
    uint32_t id;
    uint16_t near_q, lo_q, width_q;  // see below; width_q == kAllAround: 4
    uint16_t pad_ = 0;

    // Metres: no point of the cell is nearer to it (rounded down).
    double nearest() const { return near_q * kNearUnit; }
    // Every direction from the cell to it lies in the pseudo-angle arc (beam_order.h)
    // [arc_lo, arc_lo + arc_width] modulo 4, widened beyond the sweep's slack; a width
    // of 4 (stairs, ramps, walls touching the cell) is every direction.
    double arc_lo() const { return lo_q * kArcUnit; }
    double arc_width() const { return width_q == kAllAround ? 4.0 : width_q * kArcUnit; }
    // nearest rounded down, the arc widened to whole units.
    static Candidate make(uint32_t id, double nearest, double arc_lo, double arc_width);
  };

  // cell: side in metres, doubled until the lists fit in max_bytes. occluders > 0: each
  // list leaves out the walls that one of its `occluders` nearest kept walls hides from
  // the whole cell (occlusion.h); 0 keeps every wall within reach.
  // sectors: a power of two, 1 to 64 (one list per cell).
  CandidateGrid(const LaserObstacles& obstacles, double cell, double rmax, size_t max_bytes, size_t occluders = 0,
                int sectors = 1);

  // The sector of a direction whose pseudo-angle is p (in [0, 4)).
  static int sector_of(double p, int sectors) {
    return std::min(sectors - 1, static_cast<int>(p * (sectors * 0.25)));  // exact: a power of two
  }
  // p's cell (nullopt outside the grid: nothing is within rmax).
  std::optional<size_t> cell_of(Point p) const { return frame_.index_of(p); }
  // One list of a cell, nearest first: sector 0 to sectors() - 1, or sectors() for the
  // wide list (with one sector, list 0 is the whole list).
  std::span<const Candidate> list(size_t cell, int sector) const {
    const size_t k = cell * lists_per_cell_ + sector;
    return {list_.data() + offsets_[k], list_.data() + offsets_[k + 1]};
  }
  // Every candidate of p's cell, list after list (a wall can be in several sectors).
  std::span<const Candidate> near(Point p) const {
    const std::optional<size_t> c = frame_.index_of(p);
    if (!c) return {};
    return {list_.data() + offsets_[*c * lists_per_cell_], list_.data() + offsets_[(*c + 1) * lists_per_cell_]};
  }

  uint32_t wall_count() const { return wall_count_; }
  double cell() const { return frame_.cell; }
  int sectors() const { return sectors_; }
  size_t cells() const { return frame_.cells(); }
  size_t entries() const { return list_.size(); }
  size_t memory_bytes() const;
  // Bytes the lists would take with this cell size (what the constructor checks).
  static size_t estimate_bytes(const LaserObstacles& obstacles, double cell, double rmax);
  // The entries per cell that estimate implies (an upper bound of the mean list).
  static double estimate_mean_list(const LaserObstacles& obstacles, double cell, double rmax);

 private:
  GridFrame frame_;
  uint32_t wall_count_ = 0;
  int sectors_ = 1;
  int lists_per_cell_ = 1;  // the sectors, and the wide list when there are several
  std::vector<uint32_t> offsets_;  // cells() * lists per cell + 1
  std::vector<Candidate> list_;
};

}  // namespace fleetmap
