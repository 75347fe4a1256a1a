#pragma once
// Walls the map does not hold, in one scan: runs of returns stopped short of the rays cast
// from the estimate whose end points lie on one straight line longer than a person or two.
//
// Why: the lost detector (lost_detector.h) leaves every beam stopped short out, as people
// or clutter (seed 000 eq. 5's uniform term). After a kidnap along a corridor, the
// tracking filter re-locked 17.5 m away on a look-alike stretch: 56 of 131 beams stopped
// short on the corridor's end wall, which the estimate's rays pass, and the detector's
// figure stayed at 1.0 (docs/localization.md, "Kidnapping"). Flagging narrow runs in
// front of farther returns as people (foreground.h) and counting the rest against the pose
// failed among 30 people, whose crowds are wider than a flag and join walls they stand
// against. A person's outline is round: over any stretch of 1.5 m, a crowd bulges by a
// person's radius (0.2 m or more) where a wall stays within the laser's noise.
//
// The line test splits a run where its points leave the chord between its ends, as the
// split step of split-and-merge line extraction (Nguyen et al. 2005, "A comparison of
// line extraction algorithms using 2D laser rangefinder"), but measures a point's
// distance along its beam, where the laser's noise is: people in a row down a corridor
// lie close to a line the beams graze, but each one's front is off it by a step in range.
#include <cstdint>
#include <vector>

namespace fleetmap::localization {

struct UnmappedWallOptions {
  double min_length = 1.5;   // metres between a piece's ends: wider than two people side by side
  double straightness = 0.15;  // metres a range may be off the chord, along its beam: 3 sigma of the laser's noise
  double max_gap = 0.5;      // metres between consecutive end points of one run
  int min_beams = 8;
  // Radians between a beam and the piece's normal: beams that meet it at a more glancing
  // angle do not count (the chord's own error, along such a beam, outgrows the noise),
  // and those that do must still span min_length and min_beams.
  double max_incidence = 1.308996938995747;  // 75 degrees
};

// Per beam, the number (1, 2, ...) of the straight piece of min_length or more its return
// belongs to among the beams flagged in `stopped_short` (consecutive beams; ranges[j] along
// beam_angles[j]), where it meets the piece head on; 0 elsewhere. A piece's beams need not
// be consecutive: those that graze it lie between.
std::vector<int> unmapped_wall_pieces(const std::vector<double>& ranges, const std::vector<double>& beam_angles,
                                      const std::vector<uint8_t>& stopped_short,
                                      const UnmappedWallOptions& options = {});

// Per beam, 1 where the return belongs to a straight piece of min_length or more among
// the beams flagged in `stopped_short` (consecutive beams; ranges[j] along beam_angles[j])
// and meets it head on.
std::vector<uint8_t> unmapped_wall_returns(const std::vector<double>& ranges, const std::vector<double>& beam_angles,
                                           const std::vector<uint8_t>& stopped_short,
                                           const UnmappedWallOptions& options = {});

}  // namespace fleetmap::localization
