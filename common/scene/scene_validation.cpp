#include "common/scene/scene_validation.h"

#include <cmath>
#include <set>
#include <stdexcept>

#include "common/geometry/number_format.h"
#include "common/map/map_validation.h"

namespace fleetmap {

std::optional<std::string> check_tag(std::string_view tag) {
  const std::string t(tag);
  if (t.empty() || t.size() > kMaxTagBytes) return "expected a tag of 1-64 bytes, got '" + t + "'";
  if (t.find(':') != std::string::npos) return "expected a tag without ':', got '" + t + "'";
  return check_text(t, "a tag");
}

std::optional<std::string> check_tag_class(std::string_view tag_class) {
  if (is_tag_class(std::string(tag_class))) return std::nullopt;
  return "expected a tag class (obstacle, landmark, interactable or dynamic), got '" + std::string(tag_class) + "'";
}

std::optional<std::string> check_description(std::string_view description) {
  if (description.size() <= kMaxDescriptionBytes) return std::nullopt;
  return "expected a description of at most 255 bytes, got " + std::to_string(description.size());
}

std::optional<std::string> check_key(std::string_view key, std::string_view what) {
  if (!key.empty() && key.size() <= kMaxKeyBytes) return std::nullopt;
  return "expected " + std::string(what) + " keys of 1-255 bytes, got '" + std::string(key) + "'";
}

std::optional<std::string> check_height_range(const HeightRange& z) {
  if (std::isfinite(z.zmin) && std::isfinite(z.zmax) && z.zmin < z.zmax) return std::nullopt;
  return "expected finite heights with zmin < zmax, got [" + format_number(z.zmin) + ", " + format_number(z.zmax) + "]";
}

std::optional<std::string> check_polygon(const Polygon& ring, std::string_view what) {
  if (auto p = polygon_problem(ring)) return std::string(what) + ": " + *p;
  return std::nullopt;
}

std::optional<std::string> check_scene(const Scene& scene) {
  std::set<std::string> keys;
  for (const EnvObject& o : scene.objects) {
    if (auto e = check_key(o.id, "object")) return e;
    if (!keys.insert(o.id).second) return "object key '" + o.id + "' appears twice";
    if (auto e = check_tag(o.tag)) return "object '" + o.id + "' tag: " + *e;
    if (o.elements.empty()) return "object '" + o.id + "': expected at least one element, got none";
    for (size_t i = 0; i < o.elements.size(); ++i) {
      const Element& el = o.elements[i];
      const std::string what = "object '" + o.id + "' element " + std::to_string(i);
      if (auto e = check_polygon(el.footprint, what + " footprint")) return e;
      if (el.z)
        if (auto e = check_height_range(*el.z)) return what + " z: " + *e;
    }
  }
  keys.clear();
  for (const AvoidedArea& a : scene.avoided) {
    if (auto e = check_key(a.id, "avoided-area")) return e;
    if (!keys.insert(a.id).second) return "avoided area '" + a.id + "' appears twice";
    if (auto e = check_polygon(a.area, "avoided area '" + a.id + "'")) return e;
  }
  if (scene.bounds)
    if (auto e = check_polygon(*scene.bounds, "bounds")) return e;
  return std::nullopt;
}

void validate_scene(const Scene& scene) {
  if (auto e = check_scene(scene)) throw std::invalid_argument(*e);
}

}  // namespace fleetmap
