#include "common/raycast/ray_caster.h"

#include <cmath>
#include <cstring>

namespace fleetmap {

double RayCaster::cast(Point origin, double angle) const { return cast_direction(origin, ray_direction(angle)); }

void RayCaster::cast_scan(Point origin, double theta, const std::vector<double>& relative_angles,
                          double* ranges) const {
  thread_local std::vector<Point> dirs;
  dirs.resize(relative_angles.size());
  scan_directions(theta, relative_angles, dirs.data());
  for (size_t i = 0; i < dirs.size(); ++i) ranges[i] = cast_direction(origin, dirs[i]);
}

void scan_directions(double theta, const std::vector<double>& relative_angles, Point* dirs) {
  // The last beam set seen by this thread and its unit vectors.
  thread_local std::vector<double> cached_angles;
  thread_local std::vector<Point> cached_units;
  const size_t n = relative_angles.size();
  if (cached_angles.size() != n ||
      (n > 0 && std::memcmp(cached_angles.data(), relative_angles.data(), n * sizeof(double)) != 0)) {
    cached_angles = relative_angles;
    cached_units.resize(n);
    for (size_t i = 0; i < n; ++i) cached_units[i] = ray_direction(relative_angles[i]);
  }
  const double c = std::cos(theta), s = std::sin(theta);
  for (size_t i = 0; i < n; ++i) {
    const Point u = cached_units[i];
    dirs[i] = {c * u.x - s * u.y, s * u.x + c * u.y};
  }
}

std::vector<double> evenly_spread_angles(int n, double fov) {
  std::vector<double> out;
  if (n <= 0) return out;
  out.reserve(n);
  if (n == 1) {
    out.push_back(0);
    return out;
  }
  for (int i = 0; i < n; ++i) out.push_back(-fov / 2 + fov * i / (n - 1));
  return out;
}

}  // namespace fleetmap
