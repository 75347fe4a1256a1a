#include "client/localization/lost_detector.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "common/geometry/segment_distance.h"

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
  const std::vector<uint8_t> wall = options.count_unmapped_walls
                                        ? unmapped_wall_returns(ranges, beams, stopped_short, options.unmapped_wall)
                                        : std::vector<uint8_t>(beams.size(), 0);
  const double open_beyond = caster.options().rmax - tolerance;
  for (size_t j = 0; j < beams.size(); ++j) {
    const double d = ranges[j] - cast[j];
    if (stopped_short[j]) {
      e.against += wall[j];
      // The pieces' places, for a detector that compares them across scans (only then:
      // this runs on every scan).
      if (wall[j] && options.unmapped_wall_persistence > 0) {
        if (j == 0 || !wall[j - 1] || !stopped_short[j - 1]) e.unmapped_walls.emplace_back();
        e.unmapped_walls.back().push_back({ranges[j] * std::cos(beams[j]), ranges[j] * std::sin(beams[j])});
      }
    } else if (std::abs(d) <= tolerance) {
      ++e.agree;
      if (cast[j] >= open_beyond) ++e.open;
    } else if (d > 0) {
      ++e.against;
    }
  }
  return e;
}

size_t LostDetector::fleeting_wall_returns(const std::vector<std::vector<Point>>& walls) {
  // Every scan's pieces are kept where the odometry alone places them, so that earlier
  // ones need not move as the robot does.
  std::vector<std::vector<Point>> placed;
  placed.reserve(walls.size());
  for (const std::vector<Point>& run : walls) {
    placed.emplace_back();
    placed.back().reserve(run.size());
    for (const Point p : run) placed.back().push_back(compose(odometry_pose_, Odometry{p.x, p.y, 0}).point());
  }
  const double d2 = options_.unmapped_wall_persistence * options_.unmapped_wall_persistence;
  const auto stood = [&](Point p) {
    for (const std::vector<std::vector<Point>>& scan : previous_walls_)
      for (const std::vector<Point>& run : scan)
        for (size_t i = 0; i < run.size(); ++i)
          if (point_segment_distance2(p, run[i], run[std::min(i + 1, run.size() - 1)]) <= d2) return true;
    return false;
  };
  size_t fleeting = 0;
  for (const std::vector<Point>& run : placed) {
    const auto near = static_cast<size_t>(std::count_if(run.begin(), run.end(), stood));
    if (2 * near < run.size()) fleeting += run.size();
  }
  previous_walls_.push_back(std::move(placed));
  while (previous_walls_.size() > options_.unmapped_wall_memory) previous_walls_.pop_front();
  return fleeting;
}

bool LostDetector::update(const ScanEvidence& evidence, const Odometry& moved) {
  if (options_.unmapped_wall_persistence <= 0) return update_counts(evidence);
  odometry_pose_ = compose(odometry_pose_, moved);
  const size_t fleeting = fleeting_wall_returns(evidence.unmapped_walls);
  return update_counts({evidence.agree, evidence.open, evidence.against - fleeting, {}});
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
  previous_walls_.clear();
  odometry_pose_ = {};
}

}  // namespace fleetmap::localization
