#pragma once
// The map model of seed 000 section 3 and appendix A (SPEC 3).
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "common/geometry/bounding_circle.h"
#include "common/geometry/geometry.h"

namespace fleetmap {

// seed 000 eq. (2): the shape type ST of an obstacle.
enum class ShapeType : int {
  ClosedPolygon = 1,
  OpenPolygon = 2,
  ClosedCurved = 3,
  OpenCurved = 4,
  Stairs = 5,
  Ramp = 6,
};

std::string_view to_string(ShapeType st);
bool is_closed(ShapeType st);  // closed polygon, closed curved, ramp

// An oriented segment, left to right seen from free space (seed 000 section 3).
struct Segment {
  Point a, b;
  double h = 0;       // height in metres
  int in_out = 0;     // 0 indoor, 1 outdoor
  std::string semantic;
  std::string note;   // trailing '%...' comment of the seed format, without the '%'
  double length() const { return distance(a, b); }
  friend bool operator==(const Segment&, const Segment&) = default;
};

struct Obstacle {
  int id = 0;
  ShapeType type = ShapeType::ClosedPolygon;
  std::string semantic;
  std::vector<Segment> segments;
  // Computed once (seed 000 section 4.1); not part of equality, derived from segments.
  Circle bound;
  void compute_bound();
  // The axis-aligned box of its segments; Rect::none() without segments.
  Rect box() const;
  friend bool operator==(const Obstacle& l, const Obstacle& r) {
    return l.id == r.id && l.type == r.type && l.semantic == r.semantic && l.segments == r.segments;
  }
};

// (mx1,my1) upper-left and (mx4,my4) lower-right corner: y grows upwards.
struct Border {
  double mx1 = 0, my1 = 0, mx4 = 0, my4 = 0;
  Rect rect() const { return {mx1, my4, mx4, my1}; }
  static Border from_rect(const Rect& r) { return {r.xmin, r.ymax, r.xmax, r.ymin}; }
  friend bool operator==(const Border&, const Border&) = default;
};

struct Map {
  Border border;
  std::vector<Obstacle> obstacles;
  size_t segment_count() const;
  void compute_bounds();  // every obstacle's bounding circle
  friend bool operator==(const Map&, const Map&) = default;
};

}  // namespace fleetmap
