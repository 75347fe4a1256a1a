#pragma once
// What a laser at height hL sees of a scene (seed 004 section III.A): every
// element whose height range contains hL (and every 2D element) stops rays on its
// footprint's outline. Added to a segment map as closed-polygon obstacles, so every
// RayCaster, `fleetmap scan` and the slices include objects without knowing of them.
#include "common/map/map.h"
#include "common/scene/scene.h"

namespace fleetmap {

// The map plus one ST 1 obstacle per element seen at laser_height, its segments as high
// as the element's top (2D elements: kObjectWallHeight), semantic "object:<tag>:<id>".
Map with_objects_at_height(const Map& map, const Scene& scene, double laser_height);

inline constexpr double kObjectWallHeight = 1000.0;  // the format's height limit

}  // namespace fleetmap
