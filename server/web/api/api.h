#pragma once
// The HTTP API as the transport (server/web/http) sees it: routes, what a handler is
// given, and how an error becomes a response (docs/web-api.md, docs/openapi.json).
//
// Who may do what (SPEC 4): people sign in with their own database account. An
// operator may read and write; an inspector may only read; robot and server accounts
// cannot sign in. Reads run on the web program's own read-only account (the pool of
// ApiContext::reader(), sql/80_web.sql); a write runs on the signed-in operator's own
// connection (ApiContext::writer()), so the database's grants decide it, as for the
// CLI. Every write calls the same function the CLI calls (goal: accept_goal,
// server/core/goal_check.h; abort and initial pose: FleetStore).
#include <functional>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include <mysql++/mysql++.h>
#include <nlohmann/json.hpp>

#include "server/core/server_config.h"

namespace fleetmap::web {

enum class WebRole { Operator, Inspector };
const char* to_string(WebRole r);  // "operator", "inspector"

struct Principal {
  std::string user;  // the database account ("fleetmap_operator")
  WebRole role = WebRole::Inspector;
};

struct ApiRequest {
  std::string method;                        // "GET", "POST", "PUT", "DELETE"
  std::string path;                          // "/api/robots/r1/goal", without the query
  std::map<std::string, std::string> query;  // decoded ("?since=10m" -> since: 10m)
  std::vector<std::string> args;             // the route's {captures}, decoded, in order
  nlohmann::json body;                       // the parsed JSON body; null when there is none
  Principal who;
};

struct ApiResponse {
  int status = 200;
  nlohmann::json body;       // sent as application/json, unless raw is set
  std::string raw;           // sent as is, with content_type
  std::string content_type;  // with raw: "application/geo+json", ...
};

// A request refused by a handler: the HTTP status, a short code and the message the
// CLI prints for the same error. Sent as
//   {"error": {"status": 422, "code": "goal_refused", "exit_code": 3, "message": "..."}}
class ApiError : public std::runtime_error {
 public:
  ApiError(int status, std::string code, const std::string& message, int exit_code = 2)
      : std::runtime_error(message), status_(status), code_(std::move(code)), exit_code_(exit_code) {}
  int status() const { return status_; }
  const std::string& code() const { return code_; }
  int exit_code() const { return exit_code_; }

 private:
  int status_;
  std::string code_;
  int exit_code_;
};

// The database for one request; each connection is this request's alone until it returns.
class ApiContext {
 public:
  virtual ~ApiContext() = default;
  virtual mysqlpp::Connection& reader() = 0;  // the web account's (read-only)
  virtual mysqlpp::Connection& writer() = 0;  // the signed-in operator's own (403 for an inspector)
  virtual const ServerConfig& planning_defaults() const = 0;  // what `fleetmap goal` plans with
};

using Handler = std::function<ApiResponse(const ApiRequest&, ApiContext&)>;

struct Route {
  std::string method;   // "GET", "POST", "PUT", "DELETE"
  std::string pattern;  // "/api/robots/{name}/goal": a {capture} matches one path segment
  bool write = false;   // needs the operator role and the CSRF token
  std::string summary;  // one line, as in docs/openapi.json
  Handler handler;
};

// Every route of the API (server/web/api/*.cpp), in the order they are matched.
std::vector<Route> api_routes();

// What a handler's exception becomes: ApiError as it says; BadInput and
// std::invalid_argument 400 (bad_input); NotFound 404 (not_found); NoPath and
// GoalRefused 422 (goal_refused / no_path); a database "access denied" 403
// (forbidden); anything else 500 (internal), with exit_code as app/exit_code_for.h
// gives it and the message as app's error_message.
ApiResponse error_response(const std::exception& e);

}  // namespace fleetmap::web
