#pragma once
// Where a point or a polygon lies on a map: inside the border, and not inside a solid
// obstacle. `map import --replace` (protocol/map_replace.h) asks it of every robot, goal,
// place and object the old map had, to find those the new map strands.
//
// A solid obstacle is a closed polygon or closed curved obstacle (ST 1, 3) with free space
// outside, i.e. whose ring runs counter-clockwise (segments run left to right seen from
// free space, seed 000 section 3; docs/map-format.md), with at least one segment of h > 0
// (a flat outline blocks nothing, seed 000 section 4.2). A clockwise ring has free space
// inside (a room seen from within); ramps are driven on (section 4.2); stairs are climbed
// by some robots; open polygons enclose nothing. The boundary counts as inside, for the
// border too: a point on the border is on the map, a point on a wall is in it.
#include <optional>
#include <string>
#include <vector>

#include "common/geometry/geometry.h"
#include "common/geometry/polygon.h"
#include "common/map/map.h"

namespace fleetmap {

class MapPlacement {
 public:
  explicit MapPlacement(const Map& map);

  // Why p is no place to be on the map ("outside the border (0, 10)-(20, 0)", "inside
  // obstacle 7 'building'"), or nothing when it is fine.
  std::optional<std::string> point_problem(Point p) const;

  // For a footprint or an area: a vertex outside the border, or (when solid_inside) every
  // vertex inside one solid obstacle, i.e. the thing is buried in it.
  std::optional<std::string> polygon_problem(const Polygon& ring, bool solid_inside) const;

  size_t solid_obstacles() const { return solids_.size(); }

 private:
  struct Solid {
    Polygon ring;
    Rect box;
    int id = 0;
    std::string semantic;
  };
  // Indices into solids_ of the obstacles whose box holds p (a grid over the border).
  std::vector<size_t> candidates(Point p) const;
  std::string border_text() const;

  Border border_;
  Rect rect_;
  std::vector<Solid> solids_;
  // Uniform grid over rect_: each cell lists the solids whose box meets it.
  double cell_ = 1;
  long cols_ = 1, rows_ = 1;
  std::vector<std::vector<size_t>> cells_;
};

}  // namespace fleetmap
