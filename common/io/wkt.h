#pragma once
// Well-known text for the semantic layer's polygons (OGC Simple Features, the text
// MariaDB's ST_GeomFromText reads): one ring, no holes, as the model has them
// (common/scene/scene.h). Also what an operator types for an avoided area.
#include <string>

#include "common/geometry/polygon.h"

namespace fleetmap {

// 'POLYGON((x y, x y, ...))' (the word in any case, blanks anywhere between tokens, the
// closing vertex optional) to a ring without the repeated vertex. Throws
// std::invalid_argument "expected ... in 'POLYGON((x y, x y, ...))', got '<wkt>'" for
// anything else: another geometry type, unbalanced parentheses, a number that is not
// finite, fewer than 3 vertices, holes, text after the last ')'. Whether the ring is a
// valid polygon (simple, non-degenerate) is polygon_problem's question, not this one's.
Polygon parse_polygon_wkt(const std::string& wkt);

// The closed ring ('POLYGON((x0 y0,x1 y1,...,x0 y0))'), numbers in their shortest
// round-trip form, so parse_polygon_wkt gives back the same doubles.
std::string polygon_to_wkt(const Polygon& ring);

}  // namespace fleetmap
