#include "common/raycast/seed_ray_caster.h"

#include <algorithm>

namespace fleetmap {

SeedRayCaster::SeedRayCaster(const Map& map, RayCasterOptions options)
    : options_(options), obstacles_(prepare_laser_obstacles(map, options.laser_height)) {}

void SeedRayCaster::cull(Point origin, std::vector<uint32_t>& kept) const {
  kept.clear();
  for (uint32_t k = 0; k < obstacles_.obstacles.size(); ++k) {
    const Circle& b = obstacles_.obstacles[k].bound;
    // Two circles meet when their centres are no farther apart than the radii's sum;
    // 1e-6 m covers the circle's own tolerance and the segment test's.
    const Point v = b.c - origin;
    const double reach = b.r + options_.rmax + 1e-6;
    if (dot(v, v) <= reach * reach) kept.push_back(k);
  }
}

double SeedRayCaster::cast_among(const std::vector<uint32_t>& kept, Point o, Point d) const {
  double best = options_.rmax;
  for (uint32_t k : kept) {
    const LaserObstacles::Entry& e = obstacles_.obstacles[k];
    if (e.special >= 0) {
      best = std::min(best, obstacles_.specials[e.special].distance(o, d));
      continue;
    }
    for (uint32_t i = e.walls_begin; i < e.walls_end; ++i)
      best = std::min(best, ray_segment_distance(obstacles_.walls[i], o, d));
  }
  return best;
}

double SeedRayCaster::cast_direction(Point origin, Point dir) const {
  thread_local std::vector<uint32_t> kept;
  cull(origin, kept);
  return cast_among(kept, origin, dir);
}

void SeedRayCaster::cast_scan(Point origin, double theta, const std::vector<double>& relative_angles,
                              double* ranges) const {
  thread_local std::vector<uint32_t> kept;
  thread_local std::vector<Point> dirs;
  cull(origin, kept);
  dirs.resize(relative_angles.size());
  scan_directions(theta, relative_angles, dirs.data());
  for (size_t i = 0; i < dirs.size(); ++i) ranges[i] = cast_among(kept, origin, dirs[i]);
}

}  // namespace fleetmap
