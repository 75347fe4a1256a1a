#include "server/web/http/dispatcher.h"

#include <algorithm>
#include <chrono>
#include <fstream>
#include <sstream>

#include <spdlog/spdlog.h>

#include "server/web/http/cookies.h"
#include "server/web/http/sign_in.h"
#include "server/web/http/static_files.h"
#include "server/web/http/tokens.h"
#include "server/web/http/web_api_context.h"

namespace fleetmap::web {
namespace http = boost::beast::http;
namespace {

constexpr const char* kCsp = "default-src 'self'; img-src 'self' data:; style-src 'self' 'unsafe-inline'";

std::string error_json(int status, const std::string& code, const std::string& message, int exit_code) {
  return nlohmann::json{{"error", {{"status", status}, {"code", code}, {"exit_code", exit_code}, {"message", message}}}}
      .dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

std::string str(boost::beast::string_view s) { return std::string(s.data(), s.size()); }

bool is_write(std::string_view method) { return method != "GET" && method != "HEAD" && method != "OPTIONS"; }

std::optional<std::string> read_whole(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

std::string media_type(std::string_view content_type) {
  std::string t(content_type.substr(0, content_type.find(';')));
  t.erase(std::remove_if(t.begin(), t.end(), [](unsigned char c) { return std::isspace(c); }), t.end());
  std::transform(t.begin(), t.end(), t.begin(), [](unsigned char c) { return std::tolower(c); });
  return t;
}

nlohmann::json parse_json_body(std::string_view content_type, const std::string& body) {
  if (body.empty()) return nullptr;
  if (media_type(content_type) != "application/json")
    throw ApiError(415, "unsupported_media_type",
                   "a request body must be application/json, got '" + std::string(content_type) + "'");
  try {
    return nlohmann::json::parse(body);
  } catch (const nlohmann::json::parse_error& e) {
    throw ApiError(400, "bad_input", std::string("the body is not valid JSON: ") + e.what());
  }
}

Dispatcher::Dispatcher(const WebConfig& config, DbSettings web, std::vector<Route> routes, ServerConfig planning)
    : config_(config),
      router_(std::move(routes)),
      readers_(std::move(web), static_cast<size_t>(config.workers)),
      sessions_(std::chrono::seconds(config.session_idle_s), config.max_sessions),
      planning_(std::move(planning)) {}

HttpResponse Dispatcher::handle(const HttpRequest& req, const std::string& peer) {
  const auto started = std::chrono::steady_clock::now();
  const std::string target = str(req.target());
  const size_t q = target.find('?');
  const std::string path = target.substr(0, q);
  const std::string query = q == std::string::npos ? "" : target.substr(q + 1);
  const bool api_path = path == "/api" || path.rfind("/api/", 0) == 0;
  HttpResponse res;
  try {
    res = api_path ? api(req, path, query, peer) : static_file(req, path);
  } catch (const ApiError& e) {
    res = error(req, e.status(), e.code(), e.what(), e.exit_code());
    if (e.status() == 429) res.set(http::field::retry_after, "60");
  } catch (const std::exception& e) {
    spdlog::error("{} {}: {}", str(req.method_string()), path, e.what());
    res = error(req, 500, "internal", "internal error; see fleetmap-web's log");
  }
  decorate(res, api_path);
  if (req.method() == http::verb::head) res.body().clear();
  spdlog::debug("{} {} {} -> {} ({} ms)", peer, str(req.method_string()), path, res.result_int(),
                std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::steady_clock::now() - started).count());
  return res;
}

HttpResponse Dispatcher::api(const HttpRequest& req, const std::string& path, const std::string& query,
                             const std::string& peer) {
  const std::string method = str(req.method_string());
  auto only = [&](const char* m) {
    if (method != m) throw ApiError(405, "method_not_allowed", method + " is not allowed on " + path + " (" + m + ")");
  };
  if (path == "/api/login") {
    only("POST");
    return login(req, peer);
  }
  if (path == "/api/logout") {
    only("POST");
    auto s = require_session(req);
    require_csrf(req, *s);
    sessions_.close(s->id);
    spdlog::info("{} signed out ({})", s->who.user, peer);
    HttpResponse r = json(req, 200, {{"user", s->who.user}, {"signed_out", true}});
    r.set(http::field::set_cookie, cleared_session_cookie(config_.tls()));
    return r;
  }
  if (path == "/api/session") {
    only("GET");
    auto s = require_session(req);
    return json(req, 200, {{"user", s->who.user}, {"role", to_string(s->who.role)}, {"csrf", s->csrf}});
  }
  if (path == "/api/openapi.json") {
    only("GET");
    auto text = read_whole(config_.openapi_file);
    if (!text) throw ApiError(404, "not_found", "no OpenAPI document at " + config_.openapi_file, 4);
    HttpResponse r{http::status::ok, req.version()};
    r.set(http::field::content_type, "application/json");
    r.body() = std::move(*text);
    r.prepare_payload();
    return r;
  }
  if (path == "/api/ws")
    throw ApiError(426, "upgrade_required", "/api/ws is a WebSocket: send an Upgrade request with the session cookie");
  // A session first: without one, no answer tells which endpoints exist.
  require_session(req);
  const RouteMatch m = router_.match(method == "HEAD" ? "GET" : method, path);
  if (m.status == 404) throw ApiError(404, "not_found", "no endpoint " + path, 4);
  if (m.status == 405) {
    HttpResponse r = error(req, 405, "method_not_allowed", method + " is not allowed on " + path + " (" + m.allow + ")");
    r.set(http::field::allow, m.allow);
    return r;
  }
  return route(req, m, path, query);
}

HttpResponse Dispatcher::login(const HttpRequest& req, const std::string& peer) {
  if (throttle_.blocked(peer))
    throw ApiError(429, "too_many_attempts", "too many failed logins from this address; try again in a minute", 1);
  const nlohmann::json body = parse_json_body(str(req[http::field::content_type]), req.body());
  if (!body.is_object() || !body.contains("user") || !body["user"].is_string() || !body.contains("password") ||
      !body["password"].is_string())
    throw ApiError(400, "bad_input", R"(expected {"user": "...", "password": "..."})");
  const std::string user = body["user"];
  SignedIn in;
  try {
    in = sign_in(readers_.settings(), user, body["password"].get<std::string>());
  } catch (const ApiError& e) {
    // Never the password: the user, the address and why.
    spdlog::warn("login of '{}' from {} refused: {} ({})", user, peer, e.what(), e.status());
    if (e.status() == 401) throttle_.failed(peer);
    throw;
  }
  throttle_.succeeded(peer);
  auto s = sessions_.open(in.who, std::move(in.connection));
  spdlog::info("{} signed in as {} from {}", s->who.user, to_string(s->who.role), peer);
  HttpResponse r = json(req, 200, {{"user", s->who.user}, {"role", to_string(s->who.role)}, {"csrf", s->csrf}});
  r.set(http::field::set_cookie, session_cookie(s->id, config_.tls()));
  return r;
}

HttpResponse Dispatcher::route(const HttpRequest& req, const RouteMatch& m, const std::string& path,
                               const std::string& query) {
  auto s = require_session(req);
  if (m.route->write || is_write(str(req.method_string()))) {
    require_csrf(req, *s);
    if (s->who.role != WebRole::Operator)
      throw ApiError(403, "forbidden", "'" + s->who.user + "' is an inspector: inspectors may only read", 1);
  }
  ApiRequest a;
  a.method = str(req.method_string());
  a.path = path;
  a.query = parse_query(query);
  a.args = m.args;
  a.body = parse_json_body(str(req[http::field::content_type]), req.body());
  a.who = s->who;
  ApiResponse out;
  try {
    WebApiContext ctx(readers_, s, planning_);
    out = m.route->handler(a, ctx);
  } catch (const std::exception& e) {
    out = error_response(e);
    if (out.status >= 500) spdlog::error("{} {}: {}", a.method, path, e.what());
  }
  HttpResponse r{static_cast<http::status>(out.status), req.version()};
  if (!out.raw.empty() || !out.content_type.empty()) {
    r.set(http::field::content_type, out.content_type.empty() ? "application/octet-stream" : out.content_type);
    r.body() = std::move(out.raw);
  } else if (out.status != 204) {
    r.set(http::field::content_type, "application/json");
    r.body() = out.body.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  }
  r.prepare_payload();
  return r;
}

HttpResponse Dispatcher::static_file(const HttpRequest& req, const std::string& path) {
  if (req.method() != http::verb::get && req.method() != http::verb::head) {
    HttpResponse r = error(req, 405, "method_not_allowed", str(req.method_string()) + " is not allowed on " + path);
    r.set(http::field::allow, "GET, HEAD");
    return r;
  }
  const auto decoded = percent_decode(path, false);
  if (!decoded) throw ApiError(400, "bad_input", "malformed percent-escape in the path");
  std::string root = config_.static_dir, relative;
  if (*decoded == "/") relative = "index.html";
  else if (decoded->rfind("/leaflet/", 0) == 0) root = config_.leaflet_dir, relative = decoded->substr(9);
  else if (decoded->rfind("/console/", 0) == 0) relative = decoded->substr(9);
  else relative = decoded->substr(1);
  const auto file = safe_file(root, relative);
  if (!file) throw ApiError(404, "not_found", "no file " + path, 4);
  auto text = read_whole(*file);
  if (!text) throw ApiError(404, "not_found", "no file " + path, 4);
  HttpResponse r{http::status::ok, req.version()};
  r.set(http::field::content_type, content_type_for(*file));
  r.body() = std::move(*text);
  r.prepare_payload();
  return r;
}

std::shared_ptr<Session> Dispatcher::session_of(const HttpRequest& req) {
  const auto it = req.find(http::field::cookie);
  if (it == req.end()) return nullptr;
  const auto id = cookie_value(str(it->value()), kSessionCookie);
  if (!id || id->empty()) return nullptr;
  return sessions_.find(*id);
}

std::shared_ptr<Session> Dispatcher::require_session(const HttpRequest& req) {
  auto s = session_of(req);
  if (!s) throw ApiError(401, "unauthorized", "sign in first (POST /api/login); no session or it expired", 1);
  return s;
}

void Dispatcher::require_csrf(const HttpRequest& req, const Session& s) const {
  const auto it = req.find("X-CSRF-Token");
  if (it == req.end() || !tokens_equal(str(it->value()), s.csrf))
    throw ApiError(403, "csrf", "a write needs the header X-CSRF-Token of this session (GET /api/session)", 1);
}

bool Dispatcher::same_origin(const HttpRequest& req) const {
  const auto origin = req.find(http::field::origin);
  if (origin == req.end()) return true;  // not a browser's cross-site request
  const std::string scheme = config_.tls() ? "https://" : "http://";
  return str(origin->value()) == scheme + str(req[http::field::host]);
}

HttpResponse Dispatcher::json(const HttpRequest& req, int status, const nlohmann::json& body) const {
  HttpResponse r{static_cast<http::status>(status), req.version()};
  r.set(http::field::content_type, "application/json");
  r.body() = body.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  r.prepare_payload();
  return r;
}

HttpResponse Dispatcher::error(const HttpRequest& req, int status, const std::string& code,
                               const std::string& message, int exit_code) const {
  if (exit_code < 0) exit_code = status == 404 ? 4 : (status == 401 || status == 403 || status >= 500) ? 1 : 2;
  HttpResponse r{static_cast<http::status>(status), req.version()};
  r.set(http::field::content_type, "application/json");
  r.body() = error_json(status, code, message, exit_code);
  r.prepare_payload();
  return r;
}

void Dispatcher::decorate(HttpResponse& res, bool api) const {
  res.set(http::field::server, "fleetmap-web");
  res.set("X-Content-Type-Options", "nosniff");
  res.set("Referrer-Policy", "no-referrer");
  if (api) res.set(http::field::cache_control, "no-store");
  else res.set("Content-Security-Policy", kCsp);
}

}  // namespace fleetmap::web
