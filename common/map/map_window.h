#pragma once
// A partial map (SPEC 5.4, seed 001 section III.B): the W x H window centred on a point,
// clipped to the map's border; segments that cross it are cut at its edge and stay
// grouped by obstacle, in map order. This is the brute-force reference: the database
// finds the candidate segments with its spatial index, then cuts them with clip_obstacle.
#include <optional>

#include "common/map/map.h"

namespace fleetmap {

// The window's rectangle intersected with the border; empty when they do not overlap.
Rect window_rect(const Border& border, Point centre, double w, double h);

// The parts of an obstacle's segments inside r (cut segments keep h, inOut, semantics
// and note), or nullopt when none is.
std::optional<Obstacle> clip_obstacle(const Obstacle& o, const Rect& r);

// Every obstacle of m clipped to r; the result's border is r.
Map clip_map(const Map& m, const Rect& r);

}  // namespace fleetmap
