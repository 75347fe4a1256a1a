#pragma once
// Shared by planning_scene_test and goal_near_test: the example room, and a judge of
// paths among objects and avoided areas written independently of the planner's
// checker (common/clearance_checker, common/planning_obstacles, common/segment_distance):
// the blocking rule restated, point_in_polygon and distance_to_polygon of
// common/geometry/polygon.h at dense samples, its own segment intersection test, and the exact
// segment distance of planning_test_util.h.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "common/geometry/polygon.h"
#include "common/scene/scene.h"
#include "common/io/scene_geojson.h"
#include "common/io/seed_format.h"
#include "planning_test_util.h"

namespace fleetmap::planning_test {

inline const Map& example_room_map() {
  static const Map m = read_seed_file(FLEETMAP_SOURCE_DIR "/maps/example-room.map");
  return m;
}

inline const Scene& example_room_scene() {
  static const Scene s = [] {
    std::ifstream in(FLEETMAP_SOURCE_DIR "/maps/example-room.geojson", std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return read_scene_geojson(text.str());
  }();
  return s;
}

inline int sign(double v) { return (v > 0) - (v < 0); }

// Do the closed segments ab and cd meet (crossing, touching or overlapping)?
inline bool segments_intersect(Point a, Point b, Point c, Point d) {
  const int o1 = sign(cross(b - a, c - a)), o2 = sign(cross(b - a, d - a));
  const int o3 = sign(cross(d - c, a - c)), o4 = sign(cross(d - c, b - c));
  auto within = [](Point p, Point q, Point r) {  // r on the line pq: within its box?
    return std::min(p.x, q.x) <= r.x && r.x <= std::max(p.x, q.x) && std::min(p.y, q.y) <= r.y &&
           r.y <= std::max(p.y, q.y);
  };
  if (o1 != o2 && o3 != o4) return true;
  return (o1 == 0 && within(a, b, c)) || (o2 == 0 && within(a, b, d)) || (o3 == 0 && within(c, d, a)) ||
         (o4 == 0 && within(c, d, b));
}

struct SceneJudge {
  std::vector<Polygon> avoided;   // never entered, not even touched
  std::vector<Polygon> blocking;  // footprints the robot's body cannot pass, and the avoided areas
  BruteClearance walls;           // the map's segments and border
  double radius;

  SceneJudge(const Map& map, const Scene& scene, double body_height, double r) : walls(map), radius(r) {
    for (const AvoidedArea& a : scene.avoided) avoided.push_back(a.area);
    blocking = avoided;
    for (const EnvObject& o : scene.objects)
      for (const Element& e : o.elements)
        if (!e.z.has_value() || e.z->zmin < body_height) blocking.push_back(e.footprint);
  }

  // Least distance from the segment ab to any blocking polygon (0 when it enters one).
  double polygon_clearance(Point a, Point b) const {
    double d2 = std::numeric_limits<double>::infinity();
    for (const Polygon& f : blocking) {
      if (point_in_polygon(a, f)) return 0;
      for (size_t i = 0; i < f.size(); ++i) d2 = std::min(d2, brute_segment_distance2(a, b, f[i], f[(i + 1) % f.size()]));
    }
    return std::sqrt(d2);
  }

  // A point the judge calls clear with some room to spare (to choose starts and goals).
  bool comfortably_clear(Point p, double spare = 1e-3) const {
    return walls.clearance(p, p) > radius + spare && polygon_clearance(p, p) > radius + spare;
  }

  // Empty when the motion ab is fine, otherwise what is wrong with it.
  std::string check_motion(Point a, Point b) const {
    for (size_t k = 0; k < avoided.size(); ++k) {
      const Polygon& area = avoided[k];
      for (size_t i = 0; i < area.size(); ++i)
        if (segments_intersect(a, b, area[i], area[(i + 1) % area.size()])) return "crosses avoided area " + std::to_string(k);
    }
    const size_t samples = std::max<size_t>(1, static_cast<size_t>(std::ceil(distance(a, b) / 0.01)));
    for (size_t s = 0; s <= samples; ++s) {
      const Point p = a + (static_cast<double>(s) / samples) * (b - a);
      for (const Polygon& area : avoided)
        if (point_in_polygon(p, area)) return "a sample is inside an avoided area";
      for (const Polygon& f : blocking)
        if (distance_to_polygon(p, f) <= radius) return "a sample is within the radius of a blocking footprint";
    }
    if (polygon_clearance(a, b) <= radius) return "passes within the radius of a blocking footprint";
    if (walls.clearance(a, b) <= radius) return "passes within the radius of a wall or the border";
    return "";
  }

  std::string check_path(const Path& path) const {
    if (path.size() == 1) return check_motion(path[0], path[0]);
    for (size_t i = 1; i < path.size(); ++i)
      if (std::string e = check_motion(path[i - 1], path[i]); !e.empty()) return "segment " + std::to_string(i) + ": " + e;
    return "";
  }
};

}  // namespace fleetmap::planning_test
