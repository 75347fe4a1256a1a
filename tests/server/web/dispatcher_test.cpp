// The request pipeline (server/web/http/dispatcher.h) without a socket or a database:
// routes injected here, sessions opened directly. What a broken transport would get
// wrong: a write without (or with another session's) CSRF token, an inspector's write,
// a forged cookie, a body that is not JSON, captures and queries, the headers.
#include "server/web/http/dispatcher.h"

#include <gtest/gtest.h>

#include "server/web/http/cookies.h"

namespace fleetmap::web {
namespace {
namespace http = boost::beast::http;

class DispatcherTest : public ::testing::Test {
 protected:
  DispatcherTest() : dispatcher_(config(), DbSettings{}, routes(), ServerConfig{}) {}

  static const WebConfig& config() {
    static WebConfig c = [] {
      WebConfig w;
      w.static_dir = "/nonexistent";
      w.openapi_file = "/nonexistent/openapi.json";
      return w;
    }();
    return c;
  }

  // An echo of what the handler was given, so the test sees what the transport decoded.
  std::vector<Route> routes() {
    auto echo = [this](const ApiRequest& r, ApiContext&) {
      ++calls_;
      ApiResponse out;
      out.body = {{"path", r.path}, {"args", r.args}, {"query", r.query}, {"body", r.body}, {"user", r.who.user}};
      return out;
    };
    return {{"GET", "/api/robots/{name}", false, "", echo},
            {"POST", "/api/robots/{name}/goal", true, "", echo},
            {"GET", "/api/fails", false, "", [](const ApiRequest&, ApiContext&) -> ApiResponse {
               throw ApiError(422, "goal_refused", "no way there", 3);
             }},
            {"GET", "/api/writes", false, "", [](const ApiRequest&, ApiContext& c) -> ApiResponse {
               c.writer();
               return {};
             }}};
  }

  HttpRequest request(http::verb method, const std::string& target, const std::shared_ptr<Session>& s = nullptr,
                      const std::string& body = "", bool csrf = true) {
    HttpRequest r{method, target, 11};
    if (s) {
      r.set(http::field::cookie, "other=1; " + std::string(kSessionCookie) + "=" + s->id);
      if (csrf) r.set("X-CSRF-Token", s->csrf);
    }
    if (!body.empty()) {
      r.set(http::field::content_type, "application/json");
      r.body() = body;
    }
    r.prepare_payload();
    return r;
  }

  std::shared_ptr<Session> sign_in(WebRole role) {
    return dispatcher_.sessions().open({role == WebRole::Operator ? "op" : "insp", role}, nullptr);
  }

  static nlohmann::json body(const HttpResponse& r) { return nlohmann::json::parse(r.body()); }

  int calls_ = 0;
  Dispatcher dispatcher_;
};

TEST_F(DispatcherTest, PassesDecodedCapturesQueryAndBody) {
  auto op = sign_in(WebRole::Operator);
  HttpResponse r = dispatcher_.handle(request(http::verb::get, "/api/robots/r%201?since=10m&crs=wgs84", op), "peer");
  ASSERT_EQ(r.result_int(), 200) << r.body();
  const auto b = body(r);
  EXPECT_EQ(b["args"][0], "r 1");
  EXPECT_EQ(b["query"]["since"], "10m");
  EXPECT_EQ(b["query"]["crs"], "wgs84");
  EXPECT_EQ(b["path"], "/api/robots/r%201");
  EXPECT_EQ(b["user"], "op");
  EXPECT_EQ(r[http::field::cache_control], "no-store");
  EXPECT_EQ(r["X-Content-Type-Options"], "nosniff");

  r = dispatcher_.handle(request(http::verb::post, "/api/robots/r1/goal", op, R"({"x": 1, "y": 2})"), "peer");
  ASSERT_EQ(r.result_int(), 200) << r.body();
  EXPECT_EQ(body(r)["body"]["x"], 1);
}

TEST_F(DispatcherTest, EveryRouteNeedsASession) {
  HttpResponse r = dispatcher_.handle(request(http::verb::get, "/api/robots/r1"), "peer");
  EXPECT_EQ(r.result_int(), 401);
  // Not even which paths exist.
  EXPECT_EQ(dispatcher_.handle(request(http::verb::get, "/api/nothing"), "peer").result_int(), 401);
  HttpRequest forged = request(http::verb::get, "/api/robots/r1");
  forged.set(http::field::cookie, std::string(kSessionCookie) + "=" + std::string(64, 'a'));
  EXPECT_EQ(dispatcher_.handle(forged, "peer").result_int(), 401);
  EXPECT_EQ(calls_, 0);
}

TEST_F(DispatcherTest, WritesNeedThisSessionsCsrfToken) {
  auto op = sign_in(WebRole::Operator);
  auto other = sign_in(WebRole::Operator);
  EXPECT_EQ(dispatcher_.handle(request(http::verb::post, "/api/robots/r1/goal", op, "{}", false), "p").result_int(), 403);
  HttpRequest wrong = request(http::verb::post, "/api/robots/r1/goal", op, "{}", false);
  wrong.set("X-CSRF-Token", other->csrf);  // valid, but another session's
  HttpResponse r = dispatcher_.handle(wrong, "p");
  EXPECT_EQ(r.result_int(), 403);
  EXPECT_EQ(body(r)["error"]["code"], "csrf");
  EXPECT_EQ(calls_, 0);
  EXPECT_EQ(dispatcher_.handle(request(http::verb::post, "/api/robots/r1/goal", op, "{}"), "p").result_int(), 200);
}

TEST_F(DispatcherTest, InspectorsOnlyRead) {
  auto insp = sign_in(WebRole::Inspector);
  EXPECT_EQ(dispatcher_.handle(request(http::verb::get, "/api/robots/r1", insp), "p").result_int(), 200);
  HttpResponse r = dispatcher_.handle(request(http::verb::post, "/api/robots/r1/goal", insp, "{}"), "p");
  EXPECT_EQ(r.result_int(), 403);
  EXPECT_EQ(body(r)["error"]["code"], "forbidden");
  // A handler asking for the writer on an inspector's behalf is refused too.
  r = dispatcher_.handle(request(http::verb::get, "/api/writes", insp), "p");
  EXPECT_EQ(r.result_int(), 403) << r.body();
  EXPECT_EQ(calls_, 1);
}

TEST_F(DispatcherTest, BodiesMustBeJson) {
  auto op = sign_in(WebRole::Operator);
  HttpResponse r = dispatcher_.handle(request(http::verb::post, "/api/robots/r1/goal", op, "{\"x\": "), "p");
  EXPECT_EQ(r.result_int(), 400);
  EXPECT_EQ(body(r)["error"]["code"], "bad_input");
  EXPECT_NE(body(r)["error"]["message"].get<std::string>().find("parse error"), std::string::npos) << r.body();
  HttpRequest text = request(http::verb::post, "/api/robots/r1/goal", op, "{}");
  text.set(http::field::content_type, "text/plain");
  EXPECT_EQ(dispatcher_.handle(text, "p").result_int(), 415);
  HttpRequest charset = request(http::verb::post, "/api/robots/r1/goal", op, "{}");
  charset.set(http::field::content_type, "application/json; charset=utf-8");
  EXPECT_EQ(dispatcher_.handle(charset, "p").result_int(), 200);
}

TEST_F(DispatcherTest, UnknownPath404WrongMethod405HandlerErrors) {
  auto op = sign_in(WebRole::Operator);
  EXPECT_EQ(dispatcher_.handle(request(http::verb::get, "/api/nothing", op), "p").result_int(), 404);
  HttpResponse r = dispatcher_.handle(request(http::verb::delete_, "/api/robots/r1", op), "p");
  EXPECT_EQ(r.result_int(), 405);
  EXPECT_EQ(r[http::field::allow], "GET");
  r = dispatcher_.handle(request(http::verb::get, "/api/fails", op), "p");
  EXPECT_EQ(r.result_int(), 422);
  EXPECT_EQ(body(r)["error"]["code"], "goal_refused");
  EXPECT_EQ(body(r)["error"]["exit_code"], 3);
  EXPECT_EQ(body(r)["error"]["message"], "no way there");
}

TEST_F(DispatcherTest, SessionAndLogout) {
  auto op = sign_in(WebRole::Operator);
  HttpResponse r = dispatcher_.handle(request(http::verb::get, "/api/session", op), "p");
  ASSERT_EQ(r.result_int(), 200);
  EXPECT_EQ(body(r)["user"], "op");
  EXPECT_EQ(body(r)["role"], "operator");
  EXPECT_EQ(body(r)["csrf"], op->csrf);
  EXPECT_EQ(dispatcher_.handle(request(http::verb::post, "/api/logout", op, "", false), "p").result_int(), 403);
  r = dispatcher_.handle(request(http::verb::post, "/api/logout", op), "p");
  EXPECT_EQ(r.result_int(), 200);
  EXPECT_NE(std::string(r[http::field::set_cookie]).find("Max-Age=0"), std::string::npos);
  EXPECT_EQ(dispatcher_.handle(request(http::verb::get, "/api/session", op), "p").result_int(), 401);
}

TEST_F(DispatcherTest, StaticMissesAre404WithThePagesHeaders) {
  HttpResponse r = dispatcher_.handle(request(http::verb::get, "/"), "p");
  EXPECT_EQ(r.result_int(), 404);
  EXPECT_NE(std::string(r["Content-Security-Policy"]).find("default-src 'self'"), std::string::npos);
  EXPECT_EQ(dispatcher_.handle(request(http::verb::get, "/leaflet/%zz"), "p").result_int(), 400);
  EXPECT_EQ(dispatcher_.handle(request(http::verb::post, "/index.html"), "p").result_int(), 405);
}

TEST_F(DispatcherTest, SameOrigin) {
  HttpRequest r{http::verb::get, "/api/ws", 11};
  r.set(http::field::host, "127.0.0.1:8080");
  EXPECT_TRUE(dispatcher_.same_origin(r));  // no Origin: not a browser's cross-site request
  r.set(http::field::origin, "http://127.0.0.1:8080");
  EXPECT_TRUE(dispatcher_.same_origin(r));
  r.set(http::field::origin, "http://evil.example");
  EXPECT_FALSE(dispatcher_.same_origin(r));
  r.set(http::field::origin, "https://127.0.0.1:8080");  // the scheme counts too
  EXPECT_FALSE(dispatcher_.same_origin(r));
}

}  // namespace
}  // namespace fleetmap::web
