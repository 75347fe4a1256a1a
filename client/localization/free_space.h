#pragma once
// Where the robot can be: inside the map's border and outside every closed obstacle
// (SPEC 3: buildings, pillars; ST 1 closed polygon and ST 3 closed curved, with walls
// higher than 0). Global initialisation draws particles uniformly from it (seed 000
// Fig. 4).
//
// A closed obstacle counts only when its segments form a closed chain: the cut obstacles
// of a window (SPEC 5.4) and the AMRL maps' loose walls (common/io/amrl_import.h) enclose
// nothing, so on those maps free space is the whole border. Particles are not kept away
// from walls: a particle too close to one scores badly and is resampled away.
#include <random>
#include <vector>

#include "common/map/map.h"

namespace fleetmap::localization {

class FreeSpace {
 public:
  explicit FreeSpace(const Map& map);

  bool contains(Point p) const;

  // Uniform over free space, by rejection from the border's rectangle; after
  // max_tries misses (a map that is nearly all obstacle) the last point drawn.
  Point sample(std::mt19937_64& rng, int max_tries = 1000) const;

  // Square metres: the border's area less the enclosed obstacles' (overlaps counted twice).
  double area() const { return area_; }
  const Rect& rect() const { return rect_; }
  size_t solid_count() const { return solids_.size(); }  // closed obstacles that enclose

 private:
  struct Solid {
    Circle bound;
    std::vector<Point> a, b;  // segment ends
  };
  Rect rect_;
  double area_ = 0;
  std::vector<Solid> solids_;
};

}  // namespace fleetmap::localization
