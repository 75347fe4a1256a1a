#pragma once
// GIS geometry, already in the map frame, as obstacles of seed 000 section 3: rings
// become closed polygons oriented left to right seen from free space, lines open
// polygons, a line up a staircase the stairs of Fig. 1. No OGR here: plain points.
#include <optional>
#include <string>
#include <vector>

#include "common/map/map.h"

namespace fleetmap {

using Chain = std::vector<Point>;

// Removes consecutive repeated vertices (a closed ring keeps its closing vertex);
// returns how many it removed.
size_t drop_repeated_vertices(Chain& c);

// Twice the signed area of a ring (first vertex repeated at the end or not): > 0 for
// counter-clockwise.
double signed_area2(const Chain& ring);

struct SegmentStyle {
  double h = 0;
  int in_out = 1;
  std::string semantic;
};

// A closed ring (first == last, >= 4 vertices) as a closed polygon (ST 1). Free space
// outside (a building, an outer ring) -> counter-clockwise; free space inside (a hole,
// a courtyard, a room seen from within) -> clockwise: either way each segment runs left
// to right for an observer in free space (seed 000 section 3). nullopt when the ring
// has fewer than 3 distinct vertices.
std::optional<Obstacle> closed_obstacle(Chain ring, bool free_space_inside, const SegmentStyle& style);

// A chain of >= 2 distinct vertices as an open polygon (ST 2), in its own direction.
std::optional<Obstacle> open_obstacle(Chain chain, const SegmentStyle& style);

// Stairs (ST 5) along the chord of a line drawn up the staircase: steps of step_depth
// (rounded to fit the chord), step_height each, width wide, and the closing segment at
// the top (seed 000 section 3.1, Fig. 1). nullopt for a chord shorter than 1 cm.
struct StairsStyle {
  double step_height = 0.17, step_depth = 0.3, width = 1.5;
  int in_out = 1;
  std::string semantic;
};
std::optional<Obstacle> stairs_obstacle(const Chain& up, const StairsStyle& style);

}  // namespace fleetmap
