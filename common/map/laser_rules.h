#pragma once
// Which parts of an obstacle a 2D laser mounted laser_height (hL) over the floor can
// see (SPEC 6, seed 000 section 4.1 and Fig. 6): the one statement of the rules that
// the ray casters (common/raycast/ray_rules.h) apply ray by ray and the slices
// (common/slicing/map_slice.h) apply to the map once.
//
//   ST 1-4  a segment with h >= hL stops the ray; a lower one is passed.
//   ST 5    stairs: the h = 0 segment closes the staircase at its top and tells an
//           upstairs robot from a downstairs one; of the steps, only those higher
//           than the laser stop a ray (the lower steps are passed).
//   ST 6    ramps: the laser meets the solid under the surface where the surface is
//           at or above hL (the surface: common/map/ramp.h).
#include "common/map/map.h"

namespace fleetmap {

// ST 1-4 (seed 000 section 4.1: the ray "crosses" segments lower than the laser).
inline bool stops_laser(double segment_height, double laser_height) { return segment_height >= laser_height; }

// ST 5: the closing segment (seed 000 Fig. 6), oriented against the steps.
inline bool is_stairs_closing(const Segment& s) { return s.h == 0; }

// ST 5: a step that stops the laser: strictly higher than it, where a wall at exactly
// hL stops it (the ray casters and the slices have always agreed on this).
inline bool stairs_step_stops_laser(const Segment& s, double laser_height) {
  return !is_stairs_closing(s) && s.h > laser_height;
}

// ST 6: where the ramp's surface is this high (RampSurface::height_at), the solid under
// it reaches the laser.
inline bool ramp_stops_laser(double surface_height, double laser_height) { return surface_height >= laser_height; }

}  // namespace fleetmap
