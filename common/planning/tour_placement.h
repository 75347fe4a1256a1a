#pragma once
// Where a tour's node goes, measured on the stored segment map (seed 003 Fig. 2 and
// Fig. 4): "nodes in corridors are in the middle of the two walls", door nodes are
// "centred between the door posts"; the robot's own pose is only where it was told.
// The seed measures corridors with a Hough transform on sonar echoes and doors as the
// narrowest gap passed; we have the map, so we cast rays on it (common/raycast).
//
//   corridor: rays left and right, perpendicular to the heading and turned by up to
//             corridor_spread either way; the pair with the shortest chord is the
//             cross-section, and the node is its middle. Any chord between two
//             parallel walls has its middle on the centre line, so the heading need
//             not be aligned with the corridor; the shortest one only keeps the
//             chord off side openings and far walls.
//   door:     a full fan of rays; among the chords from a hit left of the heading line
//             to a hit right of it that cross the line within door_window of the pose,
//             the shortest one whose crossing point the robot sees free along its
//             heading (not a wall in front of it) and whose middle has the posts as
//             its nearest walls (clearance about half the chord: not a chord cutting
//             a corner) spans the doorway; the node is its middle. This works on walls drawn as single lines, where a ray from
//             inside the gap along the wall would touch nothing.
//   crossing: the point of most clearance (nearest wall, 72 rays) on a 0.1 m grid within
//             crossing_window of the pose: where corridors cross, the clearance is
//             largest at the middle, between the corners.
//
// Each falls back to the pose (measured = false) when nothing fits: an open side,
// no gap near the pose, no wall within reach of a crossing.
#include "common/geometry/geometry.h"
#include "common/planning/tour_event.h"
#include "common/raycast/ray_caster.h"

namespace fleetmap {

struct TourPlacementOptions {
  double corridor_spread = 0.785;  // radians (45°) either side of the perpendicular
  double angle_step = 0.00873;     // radians (0.5°) between corridor chords
  double door_window = 1.5;        // metres along the heading, either way
  int door_rays = 1440;            // rays of the door fan (0.25°)
  double min_gap = 0.4;            // metres: no robot passes a narrower gap
  double max_width = 8.0;          // metres: a wider chord is no corridor or door
  double crossing_window = 1.0;    // metres either way of the pose, in x and y
};

struct Placement {
  Point pos;              // the node's position
  bool measured = false;  // false: the pose, nothing measured
  double width = 0;       // the chord's length (corridor or door width) when measured
};

// The caster's rmax should be at least max_width: rays that reach rmax meet no wall.
Placement centre_in_corridor(const RayCaster& caster, const TourPose& pose, const TourPlacementOptions& o = {});
Placement centre_in_doorway(const RayCaster& caster, const TourPose& pose, const TourPlacementOptions& o = {});
// width: twice the clearance found.
Placement centre_in_crossing(const RayCaster& caster, const TourPose& pose, const TourPlacementOptions& o = {});

}  // namespace fleetmap
