#pragma once
// Rules a scene (common/scene/scene.h) must satisfy before it is stored, whatever its
// source (a GeoJSON file, an operator's command). The limits are the database
// columns' (sql/60_semantic.sql). Each check returns an "expected ..., got ..."
// message naming the field, or nullopt when the value is valid.
#include <optional>
#include <string>
#include <string_view>

#include "common/scene/scene.h"

namespace fleetmap {

inline constexpr size_t kMaxTagBytes = 64;
inline constexpr size_t kMaxKeyBytes = 255;          // object and avoided-area keys
inline constexpr size_t kMaxDescriptionBytes = 255;  // a tag's description

// 1-64 bytes of semantic text (check_text) without ':', which separates tag and key in
// an object's segment semantic "object:<tag>:<key>" (common/slicing/scene_laser.h).
std::optional<std::string> check_tag(std::string_view tag);
// One of is_tag_class's classes (seed 002 section 3.2).
std::optional<std::string> check_tag_class(std::string_view tag_class);
std::optional<std::string> check_description(std::string_view description);
// what: "object" or "avoided-area", for the message.
std::optional<std::string> check_key(std::string_view key, std::string_view what);
// Finite, zmin < zmax.
std::optional<std::string> check_height_range(const HeightRange& z);
// polygon_problem's rules, the message prefixed with what ("object 'x' element 0: ...").
std::optional<std::string> check_polygon(const Polygon& ring, std::string_view what);

// Every object and avoided area: keys present, short enough and unique within their
// kind, tags, at least one element per object, footprints, height ranges; the bounds.
std::optional<std::string> check_scene(const Scene& scene);

// check_scene, thrown as std::invalid_argument.
void validate_scene(const Scene& scene);

}  // namespace fleetmap
