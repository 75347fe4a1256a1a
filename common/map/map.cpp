#include "common/map/map.h"

namespace fleetmap {

std::string_view to_string(ShapeType st) {
  switch (st) {
    case ShapeType::ClosedPolygon: return "closed polygon";
    case ShapeType::OpenPolygon: return "open polygon";
    case ShapeType::ClosedCurved: return "closed curved";
    case ShapeType::OpenCurved: return "open curved";
    case ShapeType::Stairs: return "stairs";
    case ShapeType::Ramp: return "ramp";
  }
  return "unknown";
}

bool is_closed(ShapeType st) {
  return st == ShapeType::ClosedPolygon || st == ShapeType::ClosedCurved || st == ShapeType::Ramp;
}

void Obstacle::compute_bound() {
  std::vector<Point> pts;
  pts.reserve(segments.size() * 2);
  for (const Segment& s : segments) {
    pts.push_back(s.a);
    pts.push_back(s.b);
  }
  bound = minimum_bounding_circle(std::move(pts));
}

Rect Obstacle::box() const {
  Rect b = Rect::none();
  for (const Segment& s : segments) {
    b.extend(s.a);
    b.extend(s.b);
  }
  return b;
}

size_t Map::segment_count() const {
  size_t n = 0;
  for (const Obstacle& o : obstacles) n += o.segments.size();
  return n;
}

void Map::compute_bounds() {
  for (Obstacle& o : obstacles) o.compute_bound();
}

}  // namespace fleetmap
