#pragma once
// A reference planner for judging RRT path lengths in tests and benchmarks, not for
// robots: A* on an 8-connected occupancy grid over the map's border.
//
// Occupancy: a cell is free when the disc of radius r + (half the cell's diagonal)
// around its centre is clear (ClearanceChecker, so the same blocking rules). Every
// point of a move between two free neighbours, diagonal ones included, is within half
// a diagonal of one of their centres, so the grid path (start, the cell centres, goal)
// keeps the robot's clearance r exactly: a path A* finds exists for the RRT too. The
// price is a grid that is a little more cautious than r, and a length that carries the
// 8-connected metric's detour (up to 8 % over the straight line).
//
// Costs are metres (1 or sqrt 2 cells); the heuristic is the octile distance, which is
// consistent, so the length is the shortest on this grid.
#include <cstdint>
#include <optional>
#include <vector>

#include "common/geometry/grid_frame.h"
#include "common/map/map.h"
#include "common/planning/path.h"
#include "common/planning/planning_obstacles.h"

namespace fleetmap {

struct GridAStarOptions {
  double resolution = 0.1;  // metres: the side of a cell
  double radius = 0.3;      // metres: the robot's
  RobotKind robot;
};

class GridAStar {
 public:
  // Throws std::invalid_argument for a resolution or radius out of range, or a grid of
  // more than 64 M cells.
  GridAStar(const Map& map, const GridAStarOptions& options);

  // Start, cell centres, goal; nullopt when the cell of start or goal is occupied or no
  // path joins them on the grid.
  std::optional<Path> solve(Point start, Point goal);

  size_t expanded() const { return expanded_; }  // by the last solve
  int nx() const { return frame_.width; }
  int ny() const { return frame_.height; }
  size_t free_cells() const;

 private:
  std::optional<uint32_t> cell_of(Point p) const;
  Point centre(uint32_t c) const;

  double res_;
  GridFrame frame_;  // over the border
  int nx_ = 0;       // frame_.width, for the neighbour arithmetic
  std::vector<uint8_t> free_;      // per cell
  std::vector<float> g_;           // per cell, valid when stamp_ == run_
  std::vector<uint32_t> stamp_;
  std::vector<uint8_t> came_from_; // neighbour index 0-7 of the parent; 8 = start
  std::vector<uint8_t> closed_;    // per cell, valid when stamp_ == run_
  uint32_t run_ = 0;
  size_t expanded_ = 0;
};

}  // namespace fleetmap
