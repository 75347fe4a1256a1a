#include "common/scene/scene_query.h"

#include <algorithm>
#include <limits>

namespace fleetmap {

double distance_to_object(Point p, const EnvObject& object) {
  double d = std::numeric_limits<double>::infinity();
  for (const Element& e : object.elements) d = std::min(d, distance_to_polygon(p, e.footprint));
  return d;
}

std::vector<NearObject> nearest_objects(const Scene& scene, Point p, const std::string& tag, int k) {
  if (k <= 0) return {};
  std::vector<NearObject> all;
  for (const EnvObject& o : scene.objects)
    if (tag.empty() || o.tag == tag) all.push_back({o.id, distance_to_object(p, o)});
  auto closer = [](const NearObject& a, const NearObject& b) {
    return a.distance < b.distance || (a.distance == b.distance && a.id < b.id);
  };
  const size_t n = std::min(all.size(), static_cast<size_t>(k));
  std::partial_sort(all.begin(), all.begin() + static_cast<std::ptrdiff_t>(n), all.end(), closer);
  all.resize(n);
  return all;
}

std::vector<std::string> containing_avoided_areas(const Scene& scene, Point p) {
  std::vector<std::string> ids;
  for (const AvoidedArea& a : scene.avoided)
    if (point_in_polygon(p, a.area)) ids.push_back(a.id);
  std::sort(ids.begin(), ids.end());
  return ids;
}

bool within_bounds(const Scene& scene, Point p) { return !scene.bounds || point_in_polygon(p, *scene.bounds); }

}  // namespace fleetmap
