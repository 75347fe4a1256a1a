#pragma once
// The semantic layer of a map (seed 002 section 3, seed 004 section II): what
// things are, beside the segment map that says where walls are.
//
//   Element          a footprint with an optional height range; without one it is 2D and
//                    blocks at every height.
//   EnvObject        id, semantic tag, one or more elements (2D, 2.5D: one element with
//                    a range, 3D: several, e.g. a table = four legs 0..0.72 + top 0.72..0.76).
//   AvoidedArea      a polygon no robot may enter (columns, keep-out zones).
//   Scene            the objects and avoided areas of one map, plus its bounds.
#include <optional>
#include <string>
#include <vector>

#include "common/geometry/polygon.h"

namespace fleetmap {

struct HeightRange {
  double zmin = 0;  // metres over the floor, zmin < zmax
  double zmax = 0;
  bool contains(double z) const { return z >= zmin && z <= zmax; }
  friend bool operator==(const HeightRange&, const HeightRange&) = default;
};

struct Element {
  Polygon footprint;
  std::optional<HeightRange> z;  // none: 2D, blocks at every height
  // A laser at this height meets the element (its range contains the height).
  bool seen_at(double laser_height) const { return !z || z->contains(laser_height); }
  // A robot whose body is this tall cannot pass over or under it.
  bool blocks_body(double body_height) const { return !z || z->zmin < body_height; }
  friend bool operator==(const Element&, const Element&) = default;
};

struct EnvObject {
  std::string id;  // unique within a map; generated on import when absent
  std::string tag;
  std::vector<Element> elements;
  bool dynamic = false;
  friend bool operator==(const EnvObject&, const EnvObject&) = default;
};

struct AvoidedArea {
  std::string id;
  Polygon area;
  friend bool operator==(const AvoidedArea&, const AvoidedArea&) = default;
};

struct Scene {
  std::optional<Polygon> bounds;
  std::vector<EnvObject> objects;
  std::vector<AvoidedArea> avoided;
  friend bool operator==(const Scene&, const Scene&) = default;
};

// Classes of the semantic table (tag -> class and properties).
struct TagInfo {
  std::string tag;
  std::string tag_class;  // "obstacle", "landmark", "interactable" or "dynamic"
  std::string description;
  friend bool operator==(const TagInfo&, const TagInfo&) = default;
};
bool is_tag_class(const std::string& s);

}  // namespace fleetmap
