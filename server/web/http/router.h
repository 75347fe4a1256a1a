#pragma once
// Which Route a request goes to (server/web/api/api.h): patterns such as
// "/api/robots/{name}/goal" matched segment by segment, captures percent-decoded.
// A path that no route has is 404; a path some route has, with another method, is 405.
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "server/web/api/api.h"

namespace fleetmap::web {

// Percent-decoding of one path segment or query part; '+' is a space only in queries.
// nullopt for a malformed escape ("%zz", "%4") or a decoded NUL.
std::optional<std::string> percent_decode(std::string_view s, bool plus_is_space);

// "a=1&b=x%20y" -> {a: 1, b: "x y"}; a key without '=' maps to "". Throws ApiError 400
// on a malformed escape.
std::map<std::string, std::string> parse_query(std::string_view query);

struct RouteMatch {
  const Route* route = nullptr;    // null: no route for this method (see status)
  std::vector<std::string> args;   // decoded captures, in order
  int status = 200;                // 404 no such path, 405 path known but not this method
  std::string allow;               // with 405: the methods the path has ("GET, POST")
};

class Router {
 public:
  explicit Router(std::vector<Route> routes);
  // path: without the query, still percent-encoded (a capture may hold an encoded '/').
  RouteMatch match(std::string_view method, std::string_view path) const;
  const std::vector<Route>& routes() const { return routes_; }

 private:
  struct Compiled {
    std::vector<std::string> parts;  // literal segments; "{}" for a capture
  };
  std::vector<Route> routes_;
  std::vector<Compiled> compiled_;
};

}  // namespace fleetmap::web
