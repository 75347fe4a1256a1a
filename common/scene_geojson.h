#pragma once
// The semantic layer's interchange format: GeoJSON (RFC 7946 structure, map frame,
// metres; issue 8). One Feature per object, avoided area or bounds:
//   properties.kind     "object" (default) | "avoid" | "bounds"
//   properties.tag      string (objects)
//   properties.z        [[zmin, zmax], ...], one per polygon of a Polygon/MultiPolygon
//                       geometry; absent: 2D
//   properties.dynamic  bool, default false
//   properties.id       optional string
// Import validates everything and throws SceneFormatError naming the feature and the
// field; export writes what import reads.
#include <set>
#include <stdexcept>
#include <string>

#include "common/scene.h"

namespace fleetmap {

class SceneFormatError : public std::runtime_error {
 public:
  // feature: index in "features", or -1 for the document itself.
  SceneFormatError(int feature, std::string field, const std::string& message);
  int feature() const { return feature_; }
  const std::string& field() const { return field_; }

 private:
  int feature_;
  std::string field_;
};

struct SceneReadOptions {
  // Tags an object may carry; empty set with check_tags = false accepts any tag.
  std::set<std::string> known_tags;
  bool check_tags = false;
};

Scene read_scene_geojson(const std::string& text, const SceneReadOptions& options = {});
std::string write_scene_geojson(const Scene& scene);

}  // namespace fleetmap
