#include "common/planning/planning_obstacles.h"

#include <algorithm>

#include "common/geometry/polygon.h"

namespace fleetmap {

bool BlockedArea::contains(Point p) const { return bounds.contains(p) && point_in_polygon(p, ring); }

void add_blocked_area(PlanningObstacles& out, std::vector<Point> ring, int obstacle_id) {
  BlockedArea area{std::move(ring), {}, obstacle_id};
  area.bounds = {area.ring[0].x, area.ring[0].y, area.ring[0].x, area.ring[0].y};
  for (size_t i = 0; i < area.ring.size(); ++i) {
    const Point p = area.ring[i];
    area.bounds = {std::min(area.bounds.xmin, p.x), std::min(area.bounds.ymin, p.y), std::max(area.bounds.xmax, p.x),
                   std::max(area.bounds.ymax, p.y)};
    out.segments.push_back({p, area.ring[(i + 1) % area.ring.size()], obstacle_id});
  }
  out.areas.push_back(std::move(area));
}

std::vector<Point> convex_hull(std::vector<Point> pts) {
  std::sort(pts.begin(), pts.end(), [](Point l, Point r) { return l.x < r.x || (l.x == r.x && l.y < r.y); });
  pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
  if (pts.size() < 3) return pts;
  std::vector<Point> hull(2 * pts.size());
  size_t k = 0;
  for (size_t i = 0; i < pts.size(); ++i) {  // lower hull
    while (k >= 2 && cross(hull[k - 1] - hull[k - 2], pts[i] - hull[k - 2]) <= 0) --k;
    hull[k++] = pts[i];
  }
  for (size_t i = pts.size() - 1, t = k + 1; i-- > 0;) {  // upper hull
    while (k >= t && cross(hull[k - 1] - hull[k - 2], pts[i] - hull[k - 2]) <= 0) --k;
    hull[k++] = pts[i];
  }
  hull.resize(k - 1);  // the last point is the first one again
  return hull;
}

PlanningObstacles prepare_planning_obstacles(const Map& map, const RobotKind& robot) {
  PlanningObstacles out;
  for (const Obstacle& o : map.obstacles) {
    switch (o.type) {
      case ShapeType::Ramp:
        break;  // seed 000 §4.2: free space
      case ShapeType::Stairs: {
        if (robot.can_climb_stairs) break;
        std::vector<Point> corners;
        for (const Segment& s : o.segments) {
          corners.push_back(s.a);
          corners.push_back(s.b);
          // The steps themselves, so that a hull that degenerates (a window that kept
          // one step) still blocks where the steps are.
          if (s.h > 0) out.segments.push_back({s.a, s.b, o.id});
        }
        std::vector<Point> hull = convex_hull(corners);
        if (hull.size() >= 3) add_blocked_area(out, std::move(hull), o.id);
        break;
      }
      default:  // ST 1-4
        for (const Segment& s : o.segments)
          if (s.h > 0) out.segments.push_back({s.a, s.b, o.id});
    }
  }
  return out;
}

}  // namespace fleetmap
