#include "server/web/http/static_files.h"

#include <filesystem>

namespace fleetmap::web {
namespace fs = std::filesystem;

std::optional<std::string> safe_file(const std::string& root, std::string_view relative) {
  if (root.empty() || relative.find('\0') != std::string_view::npos || relative.find('\\') != std::string_view::npos)
    return std::nullopt;
  // Every segment is checked, not only a leading one: "a/../../x" must not pass.
  for (size_t start = 0; start <= relative.size();) {
    const size_t slash = relative.find('/', start);
    const std::string_view seg = relative.substr(start, slash == std::string_view::npos ? std::string_view::npos : slash - start);
    if (seg == "..") return std::nullopt;
    if (slash == std::string_view::npos) break;
    start = slash + 1;
  }
  if (!relative.empty() && relative.front() == '/') return std::nullopt;
  std::error_code ec;
  const fs::path base = fs::canonical(root, ec);
  if (ec) return std::nullopt;
  const fs::path file = fs::canonical(base / fs::path(std::string(relative)), ec);
  if (ec) return std::nullopt;
  // The prefix check on whole path components: "/srv/console2" is not under "/srv/console".
  auto b = base.begin(), f = file.begin();
  for (; b != base.end(); ++b, ++f)
    if (f == file.end() || *b != *f) return std::nullopt;
  if (!fs::is_regular_file(file, ec)) return std::nullopt;
  return file.string();
}

std::string content_type_for(std::string_view path) {
  const size_t dot = path.rfind('.');
  const std::string_view ext = dot == std::string_view::npos ? std::string_view{} : path.substr(dot + 1);
  if (ext == "html" || ext == "htm") return "text/html; charset=utf-8";
  if (ext == "js" || ext == "mjs") return "text/javascript; charset=utf-8";
  if (ext == "css") return "text/css; charset=utf-8";
  if (ext == "png") return "image/png";
  if (ext == "svg") return "image/svg+xml";
  if (ext == "json" || ext == "map") return "application/json";
  return "application/octet-stream";
}

}  // namespace fleetmap::web
