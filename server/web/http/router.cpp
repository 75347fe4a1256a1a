#include "server/web/http/router.h"

namespace fleetmap::web {
namespace {

std::vector<std::string_view> segments(std::string_view path) {
  std::vector<std::string_view> out;
  if (!path.empty() && path.front() == '/') path.remove_prefix(1);
  while (true) {
    const size_t slash = path.find('/');
    out.push_back(path.substr(0, slash));
    if (slash == std::string_view::npos) break;
    path.remove_prefix(slash + 1);
  }
  return out;
}

int hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

}  // namespace

std::optional<std::string> percent_decode(std::string_view s, bool plus_is_space) {
  std::string out;
  out.reserve(s.size());
  for (size_t i = 0; i < s.size(); ++i) {
    const char c = s[i];
    if (c == '%') {
      if (i + 2 >= s.size()) return std::nullopt;
      const int hi = hex_digit(s[i + 1]), lo = hex_digit(s[i + 2]);
      if (hi < 0 || lo < 0) return std::nullopt;
      const char d = static_cast<char>(hi * 16 + lo);
      if (d == '\0') return std::nullopt;
      out.push_back(d);
      i += 2;
    } else if (c == '+' && plus_is_space) {
      out.push_back(' ');
    } else {
      out.push_back(c);
    }
  }
  return out;
}

std::map<std::string, std::string> parse_query(std::string_view query) {
  std::map<std::string, std::string> out;
  while (!query.empty()) {
    const size_t amp = query.find('&');
    const std::string_view part = query.substr(0, amp);
    query = amp == std::string_view::npos ? std::string_view{} : query.substr(amp + 1);
    if (part.empty()) continue;
    const size_t eq = part.find('=');
    auto key = percent_decode(part.substr(0, eq), true);
    auto value = eq == std::string_view::npos ? std::optional<std::string>("") : percent_decode(part.substr(eq + 1), true);
    if (!key || !value) throw ApiError(400, "bad_input", "malformed percent-escape in the query: '" + std::string(part) + "'");
    out[*key] = *value;
  }
  return out;
}

Router::Router(std::vector<Route> routes) : routes_(std::move(routes)) {
  for (const Route& r : routes_) {
    Compiled c;
    for (std::string_view s : segments(r.pattern))
      c.parts.emplace_back(s.size() >= 2 && s.front() == '{' && s.back() == '}' ? "{}" : std::string(s));
    compiled_.push_back(std::move(c));
  }
}

RouteMatch Router::match(std::string_view method, std::string_view path) const {
  const std::vector<std::string_view> segs = segments(path);
  RouteMatch out;
  out.status = 404;
  for (size_t i = 0; i < routes_.size(); ++i) {
    const Compiled& c = compiled_[i];
    if (c.parts.size() != segs.size()) continue;
    std::vector<std::string> args;
    bool ok = true;
    for (size_t k = 0; k < segs.size() && ok; ++k) {
      if (c.parts[k] == "{}") {
        auto d = segs[k].empty() ? std::nullopt : percent_decode(segs[k], false);
        if (d) args.push_back(std::move(*d));
        else ok = false;
      } else {
        ok = c.parts[k] == segs[k];
      }
    }
    if (!ok) continue;
    if (routes_[i].method == method) {
      out.route = &routes_[i];
      out.args = std::move(args);
      out.status = 200;
      out.allow.clear();
      return out;
    }
    out.status = 405;
    if (out.allow.find(routes_[i].method) == std::string::npos)
      out.allow += (out.allow.empty() ? "" : ", ") + routes_[i].method;
  }
  return out;
}

}  // namespace fleetmap::web
