#pragma once
// Calling fleetmap-web's routes (server/web/api/api.h) the way the transport does, without
// HTTP: find the Route by method and pattern, capture its {segments}, run the handler,
// and turn an exception into error_response's answer. The ApiContext reads as the web
// account and writes as the account given (the operator, or an inspector: then the
// database itself refuses the write, SPEC 4).
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <mysql++/mysql++.h>
#include <nlohmann/json.hpp>

#include "protocol/db_settings.h"
#include "server/web/api/api.h"
#include "tests/integration/test_db.h"

namespace fleetmap::test {

class TestApiContext : public web::ApiContext {
 public:
  explicit TestApiContext(Role writer = Role::Operator)
      : reader_(connect_as(Role::Web)), writer_(connect_as(writer)) {}
  mysqlpp::Connection& reader() override { return *reader_; }
  mysqlpp::Connection& writer() override { return *writer_; }
  const ServerConfig& planning_defaults() const override { return defaults_; }

 private:
  std::unique_ptr<mysqlpp::Connection> reader_, writer_;
  ServerConfig defaults_;
};

inline std::vector<std::string> path_segments(const std::string& path) {
  std::vector<std::string> out;
  size_t start = 1;  // after the leading '/'
  while (start <= path.size()) {
    const size_t slash = path.find('/', start);
    out.push_back(path.substr(start, slash == std::string::npos ? std::string::npos : slash - start));
    if (slash == std::string::npos) break;
    start = slash + 1;
  }
  return out;
}

// The route for method + path and its captures; throws when none matches.
inline const web::Route& find_route(const std::vector<web::Route>& routes, const std::string& method,
                                    const std::string& path, std::vector<std::string>* args) {
  const std::vector<std::string> segments = path_segments(path);
  for (const web::Route& r : routes) {
    if (r.method != method) continue;
    const std::vector<std::string> pattern = path_segments(r.pattern);
    if (pattern.size() != segments.size()) continue;
    std::vector<std::string> captured;
    bool match = true;
    for (size_t i = 0; match && i < pattern.size(); ++i) {
      if (pattern[i].size() > 2 && pattern[i].front() == '{' && pattern[i].back() == '}') captured.push_back(segments[i]);
      else match = pattern[i] == segments[i];
    }
    if (!match) continue;
    *args = std::move(captured);
    return r;
  }
  throw std::runtime_error("no route for " + method + " " + path);
}

struct Answer {
  int status = 0;
  nlohmann::json body;  // parsed from raw too (GeoJSON)
  std::string content_type;
};

inline Answer call(web::ApiContext& ctx, const std::string& method, const std::string& path,
                   const nlohmann::json& body = nullptr, const std::map<std::string, std::string>& query = {}) {
  static const std::vector<web::Route> routes = web::api_routes();
  web::ApiRequest req;
  req.method = method;
  req.path = path;
  req.query = query;
  req.body = body;
  req.who = {"fleetmap_operator", web::WebRole::Operator};
  const web::Route& route = find_route(routes, method, path, &req.args);
  web::ApiResponse r;
  try {
    r = route.handler(req, ctx);
  } catch (const std::exception& e) {
    r = web::error_response(e);
  }
  Answer a;
  a.status = r.status;
  a.content_type = r.raw.empty() ? "application/json" : r.content_type;
  a.body = r.raw.empty() ? r.body : nlohmann::json::parse(r.raw);
  return a;
}

}  // namespace fleetmap::test
