#pragma once
// Plain queries on a Scene (seed 002 section 3.3), by brute force over every
// object and area: the reference the database's spatial queries are tested against.
#include <string>
#include <vector>

#include "common/scene/scene.h"

namespace fleetmap {

struct NearObject {
  std::string id;
  double distance = 0;  // metres to the object's footprint: 0 inside or on its outline
  friend bool operator==(const NearObject&, const NearObject&) = default;
};

// Distance from p to an object: the least over its elements of distance_to_polygon,
// whatever their height ranges (a table top is as near as its legs).
double distance_to_object(Point p, const EnvObject& object);

// The k objects nearest to p (tag empty: any tag), nearest first, equal distances by id.
// k <= 0 gives none.
std::vector<NearObject> nearest_objects(const Scene& scene, Point p, const std::string& tag, int k);

// Ids of the avoided areas that contain p (their outline included), sorted.
std::vector<std::string> containing_avoided_areas(const Scene& scene, Point p);

// p lies within the scene's bounds (outline included); true when it has none.
bool within_bounds(const Scene& scene, Point p);

}  // namespace fleetmap
