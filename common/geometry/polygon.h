#pragma once
// Simple polygons in the map frame (metres): the footprints of environment objects, the
// avoided areas and the bounds of a map (seed 002 section 3).
#include <optional>
#include <string>
#include <vector>

#include "common/geometry/geometry.h"

namespace fleetmap {

// An outer ring, vertices in order, without repeating the first one at the end. Either
// orientation is accepted; holes are not part of the model.
using Polygon = std::vector<Point>;

// What is wrong with a ring, or nothing: fewer than 3 distinct points, zero area, a
// non-finite coordinate, or two edges that cross or touch away from their shared vertex.
// Two equal consecutive vertices (a zero-length edge) are refused too. The tests are
// exact (orientation signs without rounding), so a point one ulp off an edge is off it.
std::optional<std::string> polygon_problem(const Polygon& ring);

// The boundary counts as inside (a point on a keep-out zone's edge is in it).
bool point_in_polygon(Point p, const Polygon& ring);

// Euclidean distance from p to the polygon's area: 0 inside or on the boundary.
double distance_to_polygon(Point p, const Polygon& ring);

double polygon_area(const Polygon& ring);  // absolute value
Rect polygon_bounds(const Polygon& ring);

// The usual footprint: a w x h rectangle centred on c, turned by yaw radians.
Polygon rectangle_footprint(Point c, double w, double h, double yaw);

}  // namespace fleetmap
