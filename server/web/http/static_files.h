#pragma once
// Files served as they are: the console (static_dir) and Leaflet (leaflet_dir). A request
// path never leaves its folder: ".." and NUL are refused, and the canonical path must
// still lie under the folder's canonical path (a symlink out of it is refused too).
#include <optional>
#include <string>
#include <string_view>

namespace fleetmap::web {

// The file under root that relative (already percent-decoded, without a leading '/')
// names, canonical; nullopt when it escapes root, is not a regular file, or does not exist.
std::optional<std::string> safe_file(const std::string& root, std::string_view relative);

// By extension: html, js, css, png, svg, json, map; anything else application/octet-stream.
std::string content_type_for(std::string_view path);

}  // namespace fleetmap::web
