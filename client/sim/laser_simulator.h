#pragma once
// The simulated 2D laser of seed 000 section 4.1 ("sensor data is simulated"): the ranges
// a RayCaster gives at the true pose, plus N(0, sigma_L) noise, clamped to [0, RMAX].
// Beams that hit nothing return RMAX exactly, as a real scanner reports no return.
//
// Unmodelled obstacles (seed 000 eq. 5's uniform term): `people` per scan, each a disc of
// person_width metres at a distance uniform between min_person_range and the wall behind
// it, covering the beams it subtends; those beams return the person's distance.
#include <cstdint>
#include <memory>
#include <random>
#include <vector>

#include "client/localization/pose.h"
#include "common/raycast/ray_caster.h"

namespace fleetmap::localization {

struct LaserSimulatorOptions {
  int beams = 131;          // NL
  double fov = kPi;         // over 180 degrees
  double sigma = 0.05;      // sigma_L, metres (seed 000 section 4.1)
  int people = 0;           // unmodelled obstacles per scan
  double person_width = 0.5;      // metres
  double min_person_range = 0.5;  // metres
};

class LaserSimulator {
 public:
  // world: the ground truth (its rmax is the laser's).
  LaserSimulator(std::shared_ptr<const RayCaster> world, LaserSimulatorOptions options, uint64_t seed);

  std::vector<double> scan(const Pose& truth);
  // The same without noise or people.
  std::vector<double> true_scan(const Pose& truth) const;

  const std::vector<double>& beam_angles() const { return beams_; }
  double rmax() const { return world_->options().rmax; }

 private:
  std::shared_ptr<const RayCaster> world_;
  LaserSimulatorOptions options_;
  std::vector<double> beams_;
  std::mt19937_64 rng_;
};

}  // namespace fleetmap::localization
