#pragma once
// What an OGR feature carries, as fleetmap text: one attribute by key, every attribute
// as the obstacle's semantic string (seed 001 section III: nothing an element carries
// is lost), lengths such as OSM's height="12 m".
#include <optional>
#include <string>

class OGRFeature;

namespace fleetmap {

// The attribute's value as text; empty when the feature has no such field or it is
// unset or null. Also finds "building:levels" laundered by OGR as "building_levels".
std::string feature_attribute(const OGRFeature& f, const std::string& key);

// Every set attribute of the feature, with "layer" and "fid", as a JSON object. The
// seed format delimiters ; # % (common/map/map_validation.h check_text) are written as
// JSON escapes (\u003b ...), so the string reads back as the same JSON and loses nothing.
std::string feature_semantic(const OGRFeature& f, const std::string& layer);

// A length in metres: "12", "12.5 m", "40 ft", "40'"; nullopt for anything else or <= 0.
std::optional<double> parse_length(const std::string& text);

// text made fit for a short semantic string or a tag: the delimiters ; # % ':' and
// control characters become '_', cut to at most max_bytes on a UTF-8 boundary.
std::string short_semantic(const std::string& text, size_t max_bytes);

}  // namespace fleetmap
