#pragma once
// What stops a laser ray, by shape type (SPEC 6, seed 000 section 4.1 and Fig. 6), for a
// laser mounted laser_height (hL) over the floor: the rules of common/map/laser_rules.h
// applied to one ray. Shared by every RayCaster, which only differ in how they find the
// candidates.
//
//   ST 1-4  a segment with h >= hL stops the ray; a lower one is passed.
//   ST 5    stairs, as a whole: when the first of its segments that the ray meets is
//           the h = 0 closing segment, the robot is upstairs and the ray crosses the
//           whole staircase; otherwise it stops at the first step with h > hL (the
//           lower steps are passed).
//   ST 6    ramps, as a whole (surface encoding in common/map/ramp.h): the ray at height hL
//           meets the solid under the surface. Where the ray enters the ramp's polygon
//           with the surface already at or above hL, it stops there (the ramp's side);
//           otherwise it stops inside, where the surface rises to hL, if it does before
//           the ray leaves the polygon.
//           A ray that starts inside the polygon (or on its outline) is cast by a robot
//           standing on the ramp: its laser tilts with it and runs parallel to the
//           surface, so the ramp never stops its rays (the seed's model has no other
//           way to place a 2D laser over a slope).
#include <cstdint>
#include <utility>
#include <variant>
#include <vector>

#include "common/geometry/bounding_circle.h"
#include "common/map/laser_rules.h"
#include "common/map/map.h"
#include "common/map/ramp.h"
#include "common/raycast/ray_segment.h"

namespace fleetmap {

class StairsRule {
 public:
  StairsRule(const Obstacle& stairs, double laser_height);
  // Distance to where the staircase stops the ray, or kNoHit.
  double distance(Point o, Point d) const;
  bool can_stop() const;  // some step is higher than the laser

 private:
  struct Part {
    RaySegment seg;
    bool closing;  // the h = 0 segment
    bool stops;    // a step with h > hL
  };
  std::vector<Part> parts_;
};

class RampRule {
 public:
  // Throws std::invalid_argument when the ramp's surface tokens are missing or wrong.
  RampRule(const Obstacle& ramp, double laser_height);
  double distance(Point o, Point d) const;
  bool contains(Point p) const;  // inside the polygon or within kRayTolerance of it
  bool can_stop() const { return ramp_stops_laser(max_height_, laser_height_); }

 private:
  RampSurface surface_;
  double laser_height_;
  double max_height_;                          // of the surface over the polygon
  std::vector<std::pair<Point, Point>> ring_;  // closed outline (gaps of a cut ramp bridged)
};

// A stairs or ramp obstacle, judged as a whole.
struct SpecialObstacle {
  std::variant<StairsRule, RampRule> rule;
  Rect bounds;  // every point where it can stop a ray lies in here
  double distance(Point o, Point d) const {
    return std::visit([&](const auto& r) { return r.distance(o, d); }, rule);
  }
};

// The obstacles of a map that can stop the laser, prepared for ray tests.
struct LaserObstacles {
  struct Entry {                              // one map obstacle, in map order
    Circle bound;                             // minimum bounding circle of its vertices (seed 000 section 4.1)
    uint32_t walls_begin = 0, walls_end = 0;  // its segments in walls, for ST 1-4
    int special = -1;                         // its index in specials, for ST 5-6
  };
  std::vector<RaySegment> walls;  // segments of ST 1-4 obstacles with h >= hL
  std::vector<SpecialObstacle> specials;
  std::vector<Entry> obstacles;  // obstacles that can stop the laser at all
  Rect bounds;                   // of everything above; empty when nothing can stop it
};

// Throws std::invalid_argument naming the obstacle when a ramp's encoding is wrong.
LaserObstacles prepare_laser_obstacles(const Map& map, double laser_height);

}  // namespace fleetmap
