#include "client/localization/lost_detector.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace fleetmap::localization {

ScanEvidence scan_evidence(const RayCaster& caster, const Pose& pose, const std::vector<double>& beams,
                           const std::vector<double>& ranges, const LostDetectorOptions& options) {
  if (ranges.size() != beams.size())
    throw std::invalid_argument("scan_evidence: expected one range per beam (" + std::to_string(beams.size()) +
                                "), got " + std::to_string(ranges.size()));
  ScanEvidence e;
  if (beams.empty()) return e;
  std::vector<double> cast(beams.size());
  caster.cast_scan(pose.point(), pose.theta, beams, cast.data());
  // A beam stopped short is explained by something the map does not hold (people,
  // clutter: seed 000 eq. 5's uniform term) and says nothing about the pose; of the
  // others, those within the tolerance agree and those that reach past a wall do not.
  // Unless the beams stopped short make a straight wall (unmapped_walls.h): the pose
  // should explain that, and they count as passing through.
  const double tolerance = options.tolerance;
  std::vector<uint8_t> stopped_short(beams.size());
  for (size_t j = 0; j < beams.size(); ++j) stopped_short[j] = ranges[j] - cast[j] < -tolerance ? 1 : 0;
  const std::vector<int> wall = options.count_unmapped_walls
                                    ? unmapped_wall_pieces(ranges, beams, stopped_short, options.unmapped_wall)
                                    : std::vector<int>(beams.size(), 0);
  // The pieces' places and the scan, for a detector that looks through earlier scans at
  // them (only then: this runs on every scan).
  const bool place_walls = options.unmapped_wall_seen_through > 0;
  const double open_beyond = caster.options().rmax - tolerance;
  for (size_t j = 0; j < beams.size(); ++j) {
    const double d = ranges[j] - cast[j];
    if (stopped_short[j]) {
      if (wall[j] == 0) continue;
      ++e.against;
      if (place_walls) {
        const auto piece = static_cast<size_t>(wall[j]);
        if (e.unmapped_walls.size() < piece) e.unmapped_walls.resize(piece);
        e.unmapped_walls[piece - 1].push_back({ranges[j] * std::cos(beams[j]), ranges[j] * std::sin(beams[j])});
      }
    } else if (std::abs(d) <= tolerance) {
      ++e.agree;
      if (cast[j] >= open_beyond) ++e.open;
    } else if (d > 0) {
      ++e.against;
    }
  }
  if (place_walls) {
    e.beams = beams;
    e.ranges = ranges;
  }
  return e;
}

bool LostDetector::seen_through(Point p) const {
  for (const Remembered& scan : previous_) {
    const std::vector<double>& beams = scan.beams;
    // Evidence built by hand may hold no scan, or readings that do not match its beams.
    if (beams.size() < 2 || scan.ranges.size() != beams.size()) continue;
    const Odometry local = between(scan.at, Pose{p.x, p.y, 0});
    const double bearing = std::atan2(local.dy, local.dx);
    const double range = std::hypot(local.dx, local.dy);
    // The beam nearest the bearing, if the bearing lies within the scan's field of view
    // (the beams ascending and evenly spread, as evenly_spread_angles gives them).
    const double half_step = 0.5 * (beams.back() - beams.front()) / static_cast<double>(beams.size() - 1);
    const auto after = std::lower_bound(beams.begin(), beams.end(), bearing);
    size_t j = static_cast<size_t>(after - beams.begin());
    if (j == beams.size() || (j > 0 && bearing - beams[j - 1] < beams[j] - bearing)) --j;
    if (std::abs(beams[j] - bearing) > half_step) continue;
    if (scan.ranges[j] > range + options_.unmapped_wall_seen_through) return true;
  }
  return false;
}

size_t LostDetector::fleeting_wall_returns(ScanEvidence& evidence) {
  // Every scan is kept where the odometry alone places it, so that earlier ones need not
  // move as the robot does; a piece is judged whole (half or more of its returns).
  const auto seen = [this](Point p) { return seen_through(compose(odometry_pose_, Odometry{p.x, p.y, 0}).point()); };
  size_t fleeting = 0;
  for (const std::vector<Point>& piece : evidence.unmapped_walls) {
    if (2 * static_cast<size_t>(std::count_if(piece.begin(), piece.end(), seen)) >= piece.size())
      fleeting += piece.size();
  }
  previous_.push_back(Remembered{odometry_pose_, std::move(evidence.beams), std::move(evidence.ranges)});
  while (previous_.size() > options_.unmapped_wall_memory) previous_.pop_front();
  return fleeting;
}

bool LostDetector::update(ScanEvidence evidence, const Odometry& moved) {
  if (options_.unmapped_wall_seen_through <= 0) return update_counts(evidence);
  odometry_pose_ = compose(odometry_pose_, moved);
  const size_t fleeting = fleeting_wall_returns(evidence);
  ScanEvidence counts;
  counts.agree = evidence.agree;
  counts.open = evidence.open;
  counts.against = evidence.against - fleeting;
  return update_counts(counts);
}

bool LostDetector::update_counts(const ScanEvidence& evidence) {
  if (evidence.telling(options_.open_beam_weight) >= static_cast<double>(options_.min_telling_beams))
    return update(evidence.share(options_.open_beam_weight));
  // A blind scan: the averages stay, and time goes on (a low fit that nothing
  // contradicts stays low for as long).
  if (updates_ == 0) return lost_;
  return judge(false);
}

bool LostDetector::update(double agreement) {
  if (updates_ == 0) {
    fast_ = slow_ = agreement;
  } else {
    fast_ += options_.fast_alpha * (agreement - fast_);
    // The slow average learns the place's usual fit only while the robot is not lost,
    // so that a long loss does not become the new normal.
    if (!lost_) slow_ += options_.slow_alpha * (agreement - slow_);
  }
  ++updates_;
  return judge(agreement < options_.floor);
}

bool LostDetector::judge(bool against) {
  const bool low = fast_ < options_.ratio * slow_ && fast_ < options_.floor;
  below_ = low ? below_ + 1 : 0;
  against_below_ = low ? against_below_ + (against ? 1 : 0) : 0;
  if (updates_ > options_.warmup && below_ >= options_.hold && against_below_ >= options_.hold_against) lost_ = true;
  return lost_;
}

void LostDetector::reset() {
  fast_ = slow_ = 0;
  updates_ = below_ = against_below_ = 0;
  lost_ = false;
  previous_.clear();
  odometry_pose_ = {};
}

}  // namespace fleetmap::localization
