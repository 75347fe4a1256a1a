#pragma once
// Distance from every cell of a grid to the nearest wall that stops the laser (the
// Euclidean distance transform of the rasterized walls): the likelihood field of Thrun,
// Burgard & Fox 2005 (section 6.4) is a function of it, and global_search.h scores
// candidate poses on it.
//
// The grid covers the map's border plus `margin` metres on every side (RMAX, so that a
// scan's end points from any pose in the border stay on the grid). Walls are the ST 1-4
// segments at least as high as the laser (common/map/laser_rules.h); stairs and ramps
// count by their segments higher than the laser, an approximation (the filter's ray
// casting, which follows ray_rules.h exactly, judges the candidates afterwards).
// Exact transform by the lower envelope of parabolas (Felzenszwalb & Huttenlocher 2012),
// one pass over columns and one over rows.
#include <cstddef>
#include <vector>

#include "common/geometry/grid_frame.h"
#include "common/map/map.h"

namespace fleetmap::localization {

struct DistanceFieldOptions {
  double resolution = 0.1;     // metres per cell
  double margin = 15.0;        // metres around the border (RMAX)
  double laser_height = 0.3;   // hL: walls lower than this are passed by the laser
  size_t max_cells = 16u << 20;  // the resolution is coarsened until the grid fits
};

class DistanceField {
 public:
  explicit DistanceField(const Map& map, DistanceFieldOptions options = {});

  const GridFrame& frame() const { return frame_; }
  int width() const { return frame_.width; }
  int height() const { return frame_.height; }
  double resolution() const { return frame_.cell; }
  Point origin() const { return frame_.origin; }  // the lower-left corner of cell (0, 0)
  size_t index(int ix, int iy) const { return frame_.index(ix, iy); }
  Point centre(int ix, int iy) const { return frame_.centre(ix, iy); }
  int cell_x(double x) const { return static_cast<int>(frame_.col(x)); }  // may be outside [0, width)
  int cell_y(double y) const { return static_cast<int>(frame_.row(y)); }
  // Metres from the cell's centre to the nearest wall cell's centre; a large value when
  // the map has no wall. Outside the grid: the value of the nearest cell.
  double distance(Point p) const;
  const std::vector<float>& distances() const { return distances_; }  // by index()

 private:
  GridFrame frame_;
  std::vector<float> distances_;
};

}  // namespace fleetmap::localization
