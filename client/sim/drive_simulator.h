#pragma once
// A robot wandering on the ground-truth map, for the tests and bench-localization: it
// drives forward in steps, its heading wandering slowly, turning away from walls it
// sees on the truth map, and reports each step's motion through noisy odometry (a draw
// of the odometry model, motion_model.h, with the robot's own noise). The path-following
// simulated robot of SPEC 6 lives in client/sim; this one needs no path or planner.
#include <cstdint>
#include <memory>
#include <random>
#include <unordered_map>
#include <vector>

#include "client/localization/free_space.h"
#include "client/localization/motion_model.h"
#include "client/localization/pose.h"
#include "common/raycast/ray_caster.h"

namespace fleetmap::localization {

struct DriveOptions {
  double step = 0.25;                  // metres driven per step (a scan every 0.25 m)
  double max_turn = deg2rad(10.0);     // heading change per step while driving
  double lookahead = 1.5;              // metres of clear way wanted ahead
  double robot_radius = 0.3;           // metres
  MotionNoise odometry{0.005, 0.0005, 0.0025, 0.0005};  // of the reported odometry
  // Drive where the map is. A way counts as clear only if, from its end, at least this
  // share of 36 rays around meets a wall within the laser's range: a fleet's robots
  // follow paths planned on their map, and do not leave it through an open door into
  // ground its laser cannot see. When no way around passes, any open way does (never
  // stuck). 0: off, the robot wanders anywhere open.
  double min_walls_around = 0;
  // Global localization's look around: the first look_around_steps steps turn in place
  // by look_around_turn each, so that the laser (180 degrees) sees behind the robot too.
  int look_around_steps = 0;
  double look_around_turn = deg2rad(60.0);
};

struct DriveStep {
  Pose truth;          // where the robot is after the step
  Odometry odometry;   // what its odometry reported of the step
  double driven = 0;   // metres actually driven (0 when turning in place)
};

class WanderDriver {
 public:
  WanderDriver(std::shared_ptr<const RayCaster> world, const Pose& start, DriveOptions options, uint64_t seed);

  DriveStep step();
  const Pose& pose() const { return pose_; }

 private:
  bool clear(double heading) const;   // lookahead free along heading, robot's width
  bool mapped(double heading) const;  // the way's end sees walls (min_walls_around)

  std::shared_ptr<const RayCaster> world_;
  DriveOptions options_;
  MotionModel odometry_;
  Pose pose_;
  double wander_ = 0;  // current turn per step, radians
  mutable std::unordered_map<uint64_t, bool> mapped_cells_;  // mapped(), by 0.25 m cell of the way's end
  int steps_ = 0;
  std::mt19937_64 rng_;
};

// A pose in free space at least `clearance` metres from every wall (36 rays around),
// from which a scan along a random heading (beams relative to it) has at least
// min_hit_fraction of its rays ending before RMAX. Throws std::runtime_error after
// max_tries draws.
Pose pick_start_pose(const FreeSpace& free_space, const RayCaster& world, const std::vector<double>& beams,
                     double min_hit_fraction, double clearance, std::mt19937_64& rng, int max_tries = 100000);

}  // namespace fleetmap::localization
