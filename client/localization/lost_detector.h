#pragma once
// Is the filter still where the robot is? Tracking follows whatever pose the cloud holds;
// a robot moved without odometry (kidnapped: lifted, pushed, a wheel slipping on a ramp)
// keeps a confident cloud at the old place, and the scans stop fitting it. The detector
// watches how well each scan fits the estimate, like AMCL's slow and fast averages of
// the weights (Thrun et al. 2005, Augmented MCL), but on a figure that does not depend
// on the sensor model's scale: the scan's agreement with rays cast from the estimate. A
// beam stopped short is explained by what the map does not hold (people, clutter: seed
// 000 eq. 5's uniform term) and is left out, unless it lies on a straight wall longer
// than people (unmapped_walls.h) that no earlier scan saw through, which the pose should
// explain; of the others, the share within `tolerance` of the cast range agree, and
// those that pass through a wall of the map do not. Measured on GDC1 (bench-localization
// --kidnaps): tracking with 10 people per scan, p5 0.75; kidnapped, median 0.3. The
// absolute share of matching beams falls to 0.45 in the median with 10 people while
// tracking, as low as a kidnapped robot's.
// The slow average learns a place's usual level (glass, doors the map has closed), so
// only a drop well below it, lasting `hold` updates, says lost.
//
//   LostDetector d;
//   d.update(scan_evidence(caster, estimate.pose, beams, ranges, d.options()), odometry);
//   if (d.lost()) { report_lost(); filter.init_global(compass); d.reset(); }
#include <deque>
#include <vector>

#include "client/localization/pose.h"
#include "client/localization/unmapped_walls.h"
#include "common/raycast/ray_caster.h"

namespace fleetmap::localization {

struct LostDetectorOptions {
  double tolerance = 0.5;  // metres: a beam agrees when |measured - cast| is within this
  // The fast average: about the last 2 scans. Among 30 people 0.5 said 117 of 128
  // kidnaps lost within 3 s where 0.3 said 115; in 12 h of driving without a kidnap it
  // said "lost" 21 times where 0.3 said 18, every time of an estimate 0.6 m or more off
  // (docs/localization.md, "A faster average"; on a drive that could leave the map).
  // Saying lost after two scans instead of three gained as much, but then one scan that
  // fits nothing is enough.
  double fast_alpha = 0.5;
  double slow_alpha = 0.02;  // the slow one: about the last 50 (the place's usual fit)
  // Lost when the fast average stays below ratio x the slow one (and below floor) for
  // hold consecutive updates. Both bounds: the ratio alone would call a place that is
  // merely harder (a glass front, doors the map has closed) lost, the floor alone a
  // place whose usual fit is low.
  // The floor sits above a look-alike corridor's fit, where a kidnapped robot's cloud
  // re-locks and still agrees with 0.5-0.65 of the beams that tell (docs/localization.md,
  // "The floor at 0.7": at 0.6 that kidnap took 3.8 s to say lost, at 0.7 1.2 s). Among 30
  // people such places agreed with 0.6-0.75 for seconds, just over both bounds at 0.7;
  // at 0.8 and 0.75, 115 of 128 kidnaps were said lost within 3 s where 104 were, and
  // every "lost" said in 6 h of driving without a kidnap still came with the estimate
  // 0.6 m or more off ("Blind scans": the bounds raised). While tracking right among 30
  // people the fast average (alpha 0.3) fell below 0.87 of the slow one on 1 scan in 1000.
  double ratio = 0.8;
  double floor = 0.75;
  int hold = 3;
  int warmup = 5;  // updates after a reset before the slow average is trusted
  // A beam stopped short on a straight piece longer than people (unmapped_walls.h) counts
  // against the pose: a wall the estimate's rays pass, as at the end of a look-alike
  // corridor (docs/localization.md, "Kidnapping").
  bool count_unmapped_walls = true;
  UnmappedWallOptions unmapped_wall;
  // A beam that reads nothing where the map has nothing within range agrees with any pose
  // on open ground: after a kidnap on the campus they were most of the beams that agreed.
  // Left out, every kidnap among 30 people was said lost within 2.6 s, but a right pose
  // with few walls in view was too: 20 "lost" in 2 h of driving where there were 3
  // (docs/localization.md, "Blind scans"). So they count, each as this much of a beam
  // that agrees (1: a whole one, 0: none). At 1 a kidnapped robot whose estimate stood on
  // open ground among 30 people kept a share over the floor with 1.6-3.4 beams against
  // per scan, as open beams outweighed them; at a quarter 121 of 128 kidnaps were said
  // lost within 3 s where 117 were, and every "lost" in 12 h of driving without a kidnap
  // still came with the estimate 0.62 m or more off ("Open beams at a quarter"; a drive
  // that could leave the map: kept on it, 1 in 12 h was said of a right pose, among 30
  // people on GDC1, "The trials' robot kept on its map").
  double open_beam_weight = 0.25;
  // A scan with fewer beams that tell (agree or against) is blind: it leaves both
  // averages as they are, but counts towards hold, since a low fit that nothing
  // contradicts stays low for as long. Among 30 people scans with no beam that tells came
  // six to thirty in a row, and counting each as full agreement lifted the fast average
  // back over the floor between the scans that told: the slowest kidnap took 8.4 s on
  // GDC1 and 9.4 s on the campus to say lost, 4.0 and 3.8 s since (docs/localization.md,
  // "Blind scans"). 0: every scan counts, one with no beam that tells as 1.
  size_t min_telling_beams = 1;
  // Of the updates below that say lost, at least this many must be scans that fit below
  // the floor themselves (the others blind, or low only through the fast average). One
  // scan of a crowd whose fronts lie nearly on a line reads as a wall the map lacks, and
  // with two blind scans after it said lost of a right pose. 2 kept quiet there, but among
  // 30 people it said 3 fewer of 64 kidnaps on GDC1 within 3 s, one of them not at all
  // (docs/localization.md, "A second scan against the pose"), so it stays 1.
  int hold_against = 1;
  size_t unmapped_wall_memory = 5;  // about a second: a crowd may hide a wall for a scan or two
  // A straight piece counts against the pose unless one of the last unmapped_wall_memory
  // scans saw through where it stands: half or more of its returns lie where a beam of
  // that scan, placed by the odometry (not by the estimate, which a kidnapped robot's
  // cloud shifts from scan to scan), read more than this many metres farther. A wall
  // stops every beam that meets it; people step into beams that passed their place a
  // moment before. A piece that no earlier scan could see past (a robot walled in by a
  // crowd, its earlier scans blind) counts from its first scan, as with 0 (off). Among 30
  // people on GDC1 the one "lost" of a right pose in 2 h went: 32 of its 46 beams against
  // had been seen through 1 s before. The kidnaps said within 3 s were the same
  // as with 0, on 4 seeds per map (docs/localization.md, "Walls seen through"). 0.3 m:
  // over 3 sigma of the laser's noise, and over a person's step towards the laser between
  // two scans. (A piece counted only once it stood in an earlier scan, tried before this,
  // cost kidnaps among 30 people: a robot walled in glimpses a wall once in seconds;
  // docs/localization.md, "Walls that stand".)
  double unmapped_wall_seen_through = 0.3;
};

// What one scan says about a pose (scan_evidence below): counts of beams.
struct ScanEvidence {
  size_t agree = 0;    // within the tolerance of the cast range
  size_t open = 0;     // of those, nothing within range in the map nor read by the laser
  size_t against = 0;  // past a wall of the map, or stopped short on a wall it lacks
  // The returns stopped short on a wall the map lacks (counted in `against`), in the
  // laser's frame (x ahead, y to the left): one straight piece each, whose beams need not
  // be consecutive (unmapped_wall_pieces: those grazing it lie between). With the scan
  // itself (beam angles, readings), to look through at the next scans' pieces; all
  // filled only for a detector that does (unmapped_wall_seen_through > 0).
  std::vector<std::vector<Point>> unmapped_walls;
  std::vector<double> beams, ranges;
  // The beams that tell, an open beam counting as open_weight of one.
  double telling(double open_weight) const {
    return static_cast<double>(agree - open + against) + open_weight * static_cast<double>(open);
  }
  // The share of telling beams that agree; 1 when none tells (nothing contradicts).
  double share(double open_weight) const {
    const double n = telling(open_weight);
    return n <= 0 ? 1.0 : (n - static_cast<double>(against)) / n;
  }
};

// Of the beams (relative angles `beams`, readings `ranges`) not stopped short of the ray
// cast from `pose`, those within options.tolerance metres of it agree and those that
// reach past it are against; a scan whose every beam was stopped short tells nothing
// (share 1). With count_unmapped_walls, beams stopped short on a
// straight piece longer than people count as ones that pass through a wall (a wall in
// front that the pose does not explain; a tracking filter that re-locked on a look-alike
// corridor after a kidnap kept 56 such beams of 131 out of the figure).
ScanEvidence scan_evidence(const RayCaster& caster, const Pose& pose, const std::vector<double>& beams,
                           const std::vector<double>& ranges, const LostDetectorOptions& options = {});

class LostDetector {
 public:
  explicit LostDetector(LostDetectorOptions options = {}) : options_(options) {}

  // One scan's agreement; returns lost().
  bool update(double agreement);
  // One scan's evidence: its share, unless fewer than min_telling_beams tell. `moved`: the
  // odometry since the previous scan (unmapped_wall_seen_through places earlier scans by it).
  // Taken by value: the detector keeps the scan it holds (a temporary is moved, not copied).
  bool update(ScanEvidence evidence, const Odometry& moved = {});
  bool lost() const { return lost_; }
  // After a new initialisation (global or the operator's pose): forget the averages.
  void reset();

  double fast() const { return fast_; }
  double slow() const { return slow_; }
  const LostDetectorOptions& options() const { return options_; }

 private:
  // The averages' verdict, counted towards hold; `against`: this scan fit below the floor.
  bool judge(bool against);
  // update(evidence) once the fleeting walls are taken out of it.
  bool update_counts(const ScanEvidence& evidence);
  // Of the evidence's wall returns (the laser's frame at odometry_pose_), those on pieces
  // that one of the last scans saw through; remembers the scan for the next (moved out of
  // the evidence).
  size_t fleeting_wall_returns(ScanEvidence& evidence);
  // Whether a beam of an earlier scan read more than unmapped_wall_seen_through past `p`
  // (the odometry's frame).
  bool seen_through(Point p) const;

  LostDetectorOptions options_;
  double fast_ = 0, slow_ = 0;
  int updates_ = 0, below_ = 0, against_below_ = 0;
  bool lost_ = false;
  Pose odometry_pose_;  // the odometry summed since reset(): the frame previous_ is in
  // One earlier scan, placed by the odometry: where it was taken, and what it read.
  struct Remembered {
    Pose at;
    std::vector<double> beams, ranges;
  };
  std::deque<Remembered> previous_;  // the last scans, newest last
};

}  // namespace fleetmap::localization
