#pragma once
// Does a robot, a disc of radius r, keep clear of the map's obstacles (SPEC 7)? At a
// point (its centre there), or swept along a straight motion (every centre on the
// segment). What blocks is decided by common/planning/planning_obstacles.h; the disc must also
// stay inside the map's border. Distances are exact (common/geometry/segment_distance.h): the
// disc is clear when every blocking segment is farther than r from its centre (touching
// at exactly r counts as a collision, so that r = 0 still forbids crossing a wall).
//
// Spatial index: a uniform grid over the area where the centre may be (the border shrunk
// by r). Each cell lists, copied inline, every blocking segment that comes within r of
// the cell (plus a hair for rounding), so a query reads only the cells its centre or
// motion passes through, and tests only segments that can be within r of it. The radius
// is fixed when the grid is built: one checker per robot size.
//
// Not common/raycast/segment_grid.h: that grid lists what stops a laser (h >= hL, stairs and
// ramps as ray rules with bounding boxes), only through each cell, for walking rays; here
// the blocking rule is the planner's and each cell must see r around it.
#include <cstdint>
#include <optional>
#include <vector>

#include "common/geometry/geometry.h"
#include "common/geometry/grid_frame.h"
#include "common/map/map.h"
#include "common/planning/planning_obstacles.h"

namespace fleetmap {

struct ClearanceOptions {
  double radius = 0.3;  // metres, >= 0
  RobotKind robot;
  double cell = 0;      // grid cell side in metres; 0: automatic (about 2 r, 0.5 to 2 m)
};

// Why a disc is not clear.
struct Collision {
  enum class Kind { Border, Segment, Area } kind;
  int obstacle_id = 0;  // for Segment and Area
};

class ClearanceChecker {
 public:
  // Throws std::invalid_argument for a negative or non-finite radius or cell.
  ClearanceChecker(const Map& map, const ClearanceOptions& options);
  // With obstacles prepared elsewhere (common/planning/planning_scene.h adds a scene's); the map
  // gives the border only, and options.robot is not used.
  ClearanceChecker(const Map& map, PlanningObstacles obstacles, const ClearanceOptions& options);

  double radius() const { return radius_; }
  // Where the disc's centre may be: the border shrunk by r (empty when r is too large).
  const Rect& free_rect() const { return free_; }

  bool point_clear(Point p) const;
  bool motion_clear(Point a, Point b) const;
  std::optional<Collision> collision(Point p) const;  // nullopt when point_clear(p)

  // The index, for benchmarks and tests.
  double cell() const { return frame_.cell; }
  size_t blocking_segments() const { return obstacles_.segments.size(); }
  size_t cell_entries() const { return entries_.size(); }
  size_t memory_bytes() const;
  const PlanningObstacles& obstacles() const { return obstacles_; }

 private:
  struct Entry {  // one blocking segment listed in one cell
    Point a, b;
    uint32_t segment;  // index into obstacles_.segments
  };
  // The entries of the grid cell nearest p.
  size_t cell_of(Point p) const { return frame_.index(frame_.clamp_col(p.x), frame_.clamp_row(p.y)); }
  bool inside_area(Point p) const;

  double radius_, r2_;
  PlanningObstacles obstacles_;
  Rect free_;
  GridFrame frame_;               // over free_
  std::vector<uint32_t> begin_;  // frame_.cells() + 1 offsets into entries_
  std::vector<Entry> entries_;
};

}  // namespace fleetmap
