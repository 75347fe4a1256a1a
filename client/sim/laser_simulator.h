#pragma once
// The simulated 2D laser of seed 000 section 4.1 ("sensor data is simulated"): the ranges
// a RayCaster gives at the true pose, plus N(0, sigma_L) noise, clamped to [0, RMAX].
// Beams that hit nothing return RMAX exactly, as a real scanner reports no return.
//
// Unmodelled obstacles (seed 000 eq. 5's uniform term): `people` walking discs, each
// person_width metres across (drawn per person within +-person_width_spread), kept in
// the scans: a person is placed in free space in the laser's field of view, in line of
// sight, at least min_person_range from the laser and clear of every wall and every other
// person; it walks at person_speed (scan_period seconds between scans) and turns to a new
// random heading when its next step would bring it against a wall, the laser or another
// person. A person that leaves the field of view, the range or the line of sight is
// placed again in view. So a scan holds up to `people` of them (they may hide one
// another); fewer where the view has no room left for one more (kPlaceAttempts). Beams
// meet the discs exactly and return the nearer of the disc and the wall, then get the
// same noise.
//
// people_field widens where people are placed and kept beyond the laser's field of view:
// 2 pi puts them all around the robot, in its line of sight and within range, as people
// walking around a robot are, so that only those in front of it reach the scans (about
// half, on the 180 degree laser). The default keeps every person in view: the harder
// reading of "people in the scans", which the localization goals are measured against.
//
// Why people never overlap: bodies do not, at a laser's height. Four overlapping discs
// side by side have fronts within 0.15 m of one line over 1.85 m, a straight piece no
// real row of people shows (docs/localization.md, "People who do not overlap").
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
  int people = 0;           // unmodelled walking people in every scan
  double person_width = 0.5;         // metres, a person's mean diameter
  double person_width_spread = 0.1;  // metres: diameters uniform in width +- spread (0.4-0.6 m)
  double min_person_range = 0.5;     // metres from the laser to a person's edge
  double person_speed = 1.0;         // metres per second, walking
  double scan_period = 0.2;          // seconds between scans (SimRobot's rate)
  double people_field = 0;           // radians around the heading where people stand; 0: the fov
};

// One simulated person: a disc in map coordinates with a walking velocity.
struct Person {
  Point centre;
  double radius = 0.25;
  Point velocity;  // metres per second
};

class LaserSimulator {
 public:
  // world: the ground truth (its rmax is the laser's).
  LaserSimulator(std::shared_ptr<const RayCaster> world, LaserSimulatorOptions options, uint64_t seed);

  // The next scan: the people walk one scan_period, then the laser reads.
  std::vector<double> scan(const Pose& truth);
  // The same without noise or people.
  std::vector<double> true_scan(const Pose& truth) const;

  const std::vector<double>& beam_angles() const { return beams_; }
  double rmax() const { return world_->options().rmax; }
  // The people of the last scan, and how many of them stood in the laser's view.
  const std::vector<Person>& people() const { return people_; }
  size_t people_in_view(const Pose& truth) const;

 private:
  bool clear_of_walls(Point c, double radius) const;
  // No other person (than self) in the disc of centre c: discs may touch, not overlap.
  bool clear_of_people(Point c, double radius, const Person* self) const;
  // Within `field` radians around the heading, the range and the line of sight.
  bool within(const Pose& truth, const Person& p, double field) const;
  bool place_in_field(const Pose& truth, Person& p);
  double field() const;  // people_field, or the fov when unset
  void walk(const Pose& truth, Person& p);

  std::shared_ptr<const RayCaster> world_;
  LaserSimulatorOptions options_;
  std::vector<double> beams_;
  std::mt19937_64 rng_;
  std::vector<Person> people_;
};

}  // namespace fleetmap::localization
