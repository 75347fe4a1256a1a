#pragma once
// Occlusion culling of a cell's candidate walls (candidate_grid.h): a wall can be left
// out of a cell's list when, from every point of the cell, some nearer wall of the list
// hides all of it. Every wall of LaserObstacles::walls stops every ray that meets it,
// so a ray that would reach the hidden wall is stopped by the occluder first, and the
// ranges do not change (tests/common/raycast/ray_caster_equivalence_test.cpp).
//
// The test is exact for one occluder O (a segment): the points q that O hides from every
// point of a convex cell C (its umbra) form a convex set, and for a fixed q the points
// of C that O hides q from form a convex set too. So O hides all of a wall W from all of
// C when it hides both ends of W from the four corners of C: eight segment crossings.
// Each is required with a margin (kOcclusionMargin) far above the exact ray test's
// tolerance and rounding, on the cell grown by it and the wall lengthened by it, so
// that the ray to any point of W crosses O's interior, strictly nearer, and O's exact
// test (ray_segment.h) reports that crossing.
#include "common/geometry/geometry.h"
#include "common/raycast/ray_segment.h"

namespace fleetmap {

inline constexpr double kOcclusionMargin = 1e-6;  // metres

// Whether O hides all of W from every point of the rectangle.
bool hides(const RaySegment& occluder, const RaySegment& wall, const Rect& cell);

}  // namespace fleetmap
