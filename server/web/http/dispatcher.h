#pragma once
// One HTTP request to its response (docs/web-api.md), with no socket in sight: the
// transport's own endpoints (login, logout, session, openapi.json), the API routes
// behind a session (CSRF on every write, SPEC 4), and the static files. Blocking (a
// login or a handler touches MySQL): the connection runs it on a worker thread.
#include <memory>
#include <string>
#include <vector>

#include <boost/beast/http.hpp>

#include "protocol/db_settings.h"
#include "server/core/server_config.h"
#include "server/web/api/api.h"
#include "server/web/http/login_throttle.h"
#include "server/web/http/reader_pool.h"
#include "server/web/http/router.h"
#include "server/web/http/session_store.h"
#include "server/web/http/web_config.h"

namespace fleetmap::web {

using HttpRequest = boost::beast::http::request<boost::beast::http::string_body>;
using HttpResponse = boost::beast::http::response<boost::beast::http::string_body>;

class Dispatcher {
 public:
  Dispatcher(const WebConfig& config, DbSettings web, std::vector<Route> routes, ServerConfig planning);

  // peer: the client's address, for the login throttle and the logs.
  HttpResponse handle(const HttpRequest& req, const std::string& peer);

  // The session the request's cookie names, or null (unknown, forged, expired).
  std::shared_ptr<Session> session_of(const HttpRequest& req);
  // False when an Origin header is present and is not this Host (a page of another site
  // opening the WebSocket with the person's cookie).
  bool same_origin(const HttpRequest& req) const;
  // An error response in the API's shape, with the transport's headers: for refusals the
  // connection makes itself (413, 431, a refused WebSocket upgrade).
  HttpResponse error(const HttpRequest& req, int status, const std::string& code, const std::string& message,
                     int exit_code = -1) const;

  SessionStore& sessions() { return sessions_; }
  ReaderPool& readers() { return readers_; }
  const WebConfig& config() const { return config_; }

 private:
  HttpResponse api(const HttpRequest& req, const std::string& path, const std::string& query, const std::string& peer);
  HttpResponse login(const HttpRequest& req, const std::string& peer);
  HttpResponse route(const HttpRequest& req, const RouteMatch& m, const std::string& path, const std::string& query);
  HttpResponse static_file(const HttpRequest& req, const std::string& path);
  std::shared_ptr<Session> require_session(const HttpRequest& req);
  void require_csrf(const HttpRequest& req, const Session& s) const;
  HttpResponse json(const HttpRequest& req, int status, const nlohmann::json& body) const;
  void decorate(HttpResponse& res, bool api) const;

  const WebConfig& config_;
  Router router_;
  ReaderPool readers_;
  SessionStore sessions_;
  LoginThrottle throttle_;
  ServerConfig planning_;
};

// "application/json; charset=utf-8" -> "application/json".
std::string media_type(std::string_view content_type);

// Parses a request body as the API takes it: null for an empty body; throws ApiError 415
// when it is not application/json, 400 (bad_input, the parser's message) when malformed.
nlohmann::json parse_json_body(std::string_view content_type, const std::string& body);

}  // namespace fleetmap::web
