// Route matching (server/web/http/router.h): captures decoded, 404 against 405, the first
// matching route wins; and query parsing.
#include "server/web/http/router.h"

#include <gtest/gtest.h>

namespace fleetmap::web {
namespace {

Route route(const std::string& method, const std::string& pattern) {
  return {method, pattern, method != "GET", "", [](const ApiRequest&, ApiContext&) { return ApiResponse{}; }};
}

Router fleet_router() {
  return Router({route("GET", "/api/maps"), route("GET", "/api/maps/{map}"), route("GET", "/api/maps/{map}/topology"),
                 route("GET", "/api/robots/{name}"), route("POST", "/api/robots/{name}/goal"),
                 route("POST", "/api/robots/{name}/abort")});
}

TEST(Router, MatchesLiteralsAndCaptures) {
  const Router r = fleet_router();
  RouteMatch m = r.match("GET", "/api/maps");
  ASSERT_NE(m.route, nullptr);
  EXPECT_EQ(m.route->pattern, "/api/maps");
  EXPECT_TRUE(m.args.empty());

  m = r.match("GET", "/api/maps/campus/topology");
  ASSERT_NE(m.route, nullptr);
  EXPECT_EQ(m.route->pattern, "/api/maps/{map}/topology");
  EXPECT_EQ(m.args, std::vector<std::string>{"campus"});

  m = r.match("POST", "/api/robots/r1/goal");
  ASSERT_NE(m.route, nullptr);
  EXPECT_EQ(m.route->pattern, "/api/robots/{name}/goal");
  EXPECT_EQ(m.args, std::vector<std::string>{"r1"});
}

TEST(Router, DecodesCaptures) {
  const Router r = fleet_router();
  RouteMatch m = r.match("GET", "/api/maps/my%20map");
  ASSERT_NE(m.route, nullptr);
  EXPECT_EQ(m.args, std::vector<std::string>{"my map"});
  // An encoded '/' stays inside its segment: it does not make another route match.
  m = r.match("GET", "/api/maps/a%2Fb");
  ASSERT_NE(m.route, nullptr);
  EXPECT_EQ(m.route->pattern, "/api/maps/{map}");
  EXPECT_EQ(m.args, std::vector<std::string>{"a/b"});
  // '+' is a plus in a path.
  EXPECT_EQ(r.match("GET", "/api/maps/a+b").args, std::vector<std::string>{"a+b"});
}

TEST(Router, UnknownPathIs404WrongMethod405) {
  const Router r = fleet_router();
  EXPECT_EQ(r.match("GET", "/api/nothing").status, 404);
  EXPECT_EQ(r.match("GET", "/api/maps/a/b/c").status, 404);
  EXPECT_EQ(r.match("GET", "/api/maps/").status, 404);  // an empty capture is no map
  EXPECT_EQ(r.match("GET", "/api/maps/%zz").status, 404);
  const RouteMatch m = r.match("DELETE", "/api/maps");
  EXPECT_EQ(m.status, 405);
  EXPECT_EQ(m.route, nullptr);
  EXPECT_EQ(m.allow, "GET");
  EXPECT_EQ(r.match("GET", "/api/robots/r1/goal").allow, "POST");
}

TEST(PercentDecode, EscapesAndMalformed) {
  EXPECT_EQ(percent_decode("a%20b%2fc", false), "a b/c");
  EXPECT_EQ(percent_decode("a+b", true), "a b");
  EXPECT_EQ(percent_decode("a+b", false), "a+b");
  EXPECT_EQ(percent_decode("%4", false), std::nullopt);
  EXPECT_EQ(percent_decode("%", false), std::nullopt);
  EXPECT_EQ(percent_decode("%g0", false), std::nullopt);
  EXPECT_EQ(percent_decode("a%00b", false), std::nullopt);
}

TEST(Query, ParsesPairs) {
  const auto q = parse_query("robot=r%201&limit=5&crs=wgs84&flag&=x&");
  EXPECT_EQ(q.at("robot"), "r 1");
  EXPECT_EQ(q.at("limit"), "5");
  EXPECT_EQ(q.at("crs"), "wgs84");
  EXPECT_EQ(q.at("flag"), "");
  EXPECT_TRUE(parse_query("").empty());
  try {
    parse_query("since=%zz");
    FAIL() << "a malformed escape must be refused";
  } catch (const ApiError& e) {
    EXPECT_EQ(e.status(), 400);
  }
}

}  // namespace
}  // namespace fleetmap::web
