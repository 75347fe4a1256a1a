#pragma once
// The semantic layer's interchange format: GeoJSON (RFC 7946 structure, map frame,
// metres; docs/semantic-layer.md). One Feature per object, avoided area or bounds:
//   properties.kind     "object" (default) | "avoid" | "bounds"
//   properties.tag      string (objects)
//   properties.z        [[zmin, zmax], ...], one per polygon of a Polygon/MultiPolygon
//                       geometry; absent: 2D
//   properties.dynamic  bool, default false
//   properties.id       optional string
// Import validates everything and throws SceneFormatError naming the feature and the
// field; export writes what import reads. docs/semantic-layer.md has the details: the
// ids generated when properties.id is absent, what each field accepts.
#include <set>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "common/io/output_frame.h"
#include "common/scene/scene.h"
#include "common/core/error.h"

namespace fleetmap {

class SceneFormatError : public BadInput {
 public:
  // feature: index in "features", or -1 for the document itself. what():
  //   feature 3 (properties.z): expected 2 ranges, one per polygon, got 1
  //   document (type): expected "FeatureCollection", got "Feature"
  // item names what is counted ("entry" in a tag table).
  SceneFormatError(int feature, std::string field, const std::string& message, std::string_view item = "feature");
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
// Throws std::invalid_argument when the scene holds what the reader refuses (a
// non-finite number, an object without elements, text that is not UTF-8).
// In another frame than the map's (WGS 84 for GIS tools), the file is an export only:
// the reader takes map-frame metres.
std::string write_scene_geojson(const Scene& scene, const OutputFrame& frame = {});

// The semantic table as a JSON array of {"tag", "class", "description"} (description
// optional), e.g. maps/example-room.tags.json. Tags unique, classes is_tag_class().
// Errors are SceneFormatError with item "entry" (the index in the array), or -1.
std::vector<TagInfo> read_tag_table_json(const std::string& text);
std::string write_tag_table_json(const std::vector<TagInfo>& tags);

}  // namespace fleetmap
