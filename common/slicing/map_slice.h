#pragma once
// Per-robot maps (seed 004): the 2D map a robot with its laser at height hL sees, i.e. the
// slice of the segment map at hL. The slice is a segment map of exactly what stops a ray
// at hL under common/raycast/ray_rules.h, so a RayCaster at hL gives the same ranges on the slice
// as on the whole map (tests/common/slicing/map_slice_test.cpp):
//
//   ST 1-4  the segments with h >= hL, unchanged; the obstacle keeps its id, type and
//           semantic string; an obstacle with no segment left is dropped. A closed
//           polygon that lost a door is an open chain now, so a slice is checked with
//           MapKind::Window, as a window is.
//   ST 5    the steps with h > hL and the h = 0 closing segment. The closing segment
//           keeps the view-dependent rule of seed 000 Fig. 6 for a ray caster that reads
//           the slice (from upstairs the ray still crosses the whole staircase); a static
//           2D picture (occupancy_grid.h) cannot hold it and shows the steps as seen from
//           below. Stairs without a step above hL are dropped.
//   ST 6    the region R of the ramp's polygon where its surface is at or above hL, as
//           walls (ST 1, the ramp's semantic string kept): the parts of the outline over
//           R, plus the line where the surface crosses hL, clipped to the polygon. Each
//           wall's h is the highest surface height along it (>= hL). A ray from outside
//           the polygon stops where it first meets R, as RampRule does; a robot standing
//           on the ramp (its rays never stop there) is not expressible in 2D. R in
//           several pieces (a concave ramp), or reduced to a line (hL at the ramp's top),
//           gives an ST 2 obstacle (MapKind::Window). Ramps whose top is below hL are
//           dropped.
//
// The border is kept. The result is valid for validate_map(slice, MapKind::Window) and
// writable with write_seed.
#include "common/map/map.h"

namespace fleetmap {

// Throws std::invalid_argument for a laser height that is not finite and >= 0, or a
// ramp whose surface encoding is wrong (naming the obstacle).
Map slice_at_height(const Map& map, double laser_height);

}  // namespace fleetmap
