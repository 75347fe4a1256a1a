#pragma once
// Global localization's first step: where on the map could the first scan have been
// taken? With the compass the heading is known within +-3 degrees (seed 000 section 4.1),
// so the search space is (x, y) over the map and a few headings. Each candidate pose is
// scored by a likelihood field (Thrun, Burgard & Fox 2005, section 6.4): the scan's end
// points are placed on the map from the pose and each adds
//
//     max(-d^2 / (2 sigma^2), -max_penalty),    d its distance to the nearest wall
//
// (distance_field.h). Unlike the ray casting of eq. (4)-(6) this costs one table read
// per beam, so every 0.1 m of the map can be tried: the uniform cloud of the seed's
// filter leaves one particle per 1.7 m2 (6000 over 10 000 m2), one per 35 m2 on the
// campus, and a particle a metre off the truth scores worse than a wrong place.
//
// Branch and bound over three resolutions (Olson, "Real-time correlative scan matching",
// 2009; Hess et al., Cartographer, 2016): a block of block x block cells is scored on
// the field max-pooled over the block, an upper bound of every pose in it, and a coarse
// block of coarse x coarse blocks on the field pooled over it; coarse blocks and blocks
// are expanded best bound first, and the search stops when no bound beats the K-th best
// block found. The coarse level spares bounding every block of a large map (the campus
// has 250 000 blocks of 0.8 m: most of a search's time with blocks alone). The result is exact: the K blocks whose best pose (on the grid of cells
// and heading steps) scores highest, each with that pose. One candidate per block keeps
// the K candidates K places, not K neighbours of one peak.
//
// Candidate positions are cells of free space (free_space.h) at least `clearance` from
// every wall: the laser is on a robot, not in a wall.
#include <cstddef>
#include <memory>
#include <vector>

#include "client/localization/distance_field.h"
#include "client/localization/pose.h"
#include "common/map/map.h"

namespace fleetmap::localization {

struct GlobalSearchOptions {
  DistanceFieldOptions field;          // resolution 0.1 m, margin RMAX, hL
  double sigma = 0.25;                 // metres: the field's tolerance (grid + heading step)
  double max_penalty = 4.5;            // per beam: the floor, at 3 sigma
  int block = 8;                       // cells per block side (0.8 m)
  int coarse = 1;                      // blocks per coarse block side (4: 3.2 m); 1: no coarse level
  double heading_step = deg2rad(1.0);  // headings tried across the compass's interval
  double clearance = 0.2;              // metres from the nearest wall
  int threads = 2;
};

struct Candidate {
  Pose pose;
  double score = 0;  // sum over the beams that hit of the per-beam terms (<= 0)
};

class GlobalSearch {
 public:
  GlobalSearch(const Map& map, GlobalSearchOptions options = {});

  // The K best candidates, best first, for a scan (ranges along beam_angles, rmax: no
  // return) taken with a heading within half_width of `heading`. Empty when no beam hit.
  // Any points in the robot's frame will do as (range, angle) pairs, e.g. several scans
  // stitched by odometry (rmax infinite); those beyond the field's margin are left out.
  std::vector<Candidate> search(const std::vector<double>& ranges, const std::vector<double>& beam_angles,
                                double rmax, double heading, double half_width, size_t k) const;

  // The score of one pose (end points rounded to cells, as the search does).
  double score(const Pose& pose, const std::vector<double>& ranges, const std::vector<double>& beam_angles,
               double rmax) const;

  const DistanceField& field() const { return field_; }
  const GlobalSearchOptions& options() const { return options_; }
  size_t last_expanded() const { return expanded_; }  // blocks scored cell by cell, last search

 private:
  GlobalSearchOptions options_;
  DistanceField field_;
  std::vector<float> score_;   // per cell: the end point's term
  std::vector<float> pooled_;  // per cell: max of score_ over [ix, ix + block) x [iy, iy + block)
  std::vector<uint8_t> allowed_;  // per cell: a candidate position
  int bx0_ = 0, by0_ = 0, bx1_ = 0, by1_ = 0;  // blocks covering the border: [bx0, bx1) x [by0, by1)
  std::vector<uint8_t> block_allowed_;         // some cell of the block is allowed
  std::vector<float> pooled_coarse_;  // per cell: max of score_ over coarse * block cells each way
  mutable size_t expanded_ = 0;
};

}  // namespace fleetmap::localization
