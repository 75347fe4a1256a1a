#include "common/slicing/scene_laser.h"

#include <algorithm>

namespace fleetmap {
namespace {

// Twice the signed area: > 0 for a counter-clockwise ring.
double signed_area2(const Polygon& ring) {
  double a = 0;
  for (size_t i = 1; i + 1 < ring.size(); ++i) a += cross(ring[i] - ring[0], ring[i + 1] - ring[0]);
  return a;
}

}  // namespace

Map with_objects_at_height(const Map& map, const Scene& scene, double laser_height) {
  Map out = map;
  // New ids after the map's largest, so they never collide with a wall's.
  int next_id = 1;
  for (const Obstacle& o : map.obstacles) next_id = std::max(next_id, o.id + 1);
  for (const EnvObject& object : scene.objects) {
    for (const Element& e : object.elements) {
      if (!e.seen_at(laser_height) || e.footprint.size() < 3) continue;
      Obstacle o;
      o.id = next_id++;
      o.type = ShapeType::ClosedPolygon;
      o.semantic = "object:" + object.tag + ":" + object.id;
      // A closed polygon with free space outside runs counter-clockwise
      // (docs/map-format.md); the footprint may come either way.
      Polygon ring = e.footprint;
      if (signed_area2(ring) < 0) std::reverse(ring.begin(), ring.end());
      const double h = e.z ? e.z->zmax : kObjectWallHeight;
      for (size_t i = 0; i < ring.size(); ++i)
        o.segments.push_back({ring[i], ring[(i + 1) % ring.size()], h, 0, object.tag, ""});
      o.compute_bound();
      out.obstacles.push_back(std::move(o));
    }
  }
  return out;
}

}  // namespace fleetmap
