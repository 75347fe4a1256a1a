// fleetmap-web's transport against the test database (docs/web-api.md): the real program
// on port 0, real operator, inspector and robot accounts signing in, the limits, static
// files, the WebSocket feed fed by a robot talking to the real fleetmap-server, and TLS
// with a certificate made here. Each test starts its own fleetmap-web, so the login
// throttle of one never blocks another.
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <set>
#include <sstream>
#include <thread>

#include <gtest/gtest.h>

#include "protocol/connection.h"
#include "protocol/fleet_store.h"
#include "tests/integration/server_fixture.h"
#include "tests/integration/test_db.h"
#include "tests/integration/web_client.h"

namespace fleetmap::test {
namespace {
using nlohmann::json;
using namespace std::chrono_literals;

// build/bin/fleetmap-web --http-port 0 on the instance's config; the port from the line
// it prints on stdout.
class WebProcess {
 public:
  explicit WebProcess(const std::string& flags = "", const std::string& log_name = "web.log")
      : log_(temp_path(log_name)) {
    std::filesystem::remove(log_);
    const std::string cmd = "exec " + std::string(FLEETMAP_BIN_DIR) + "/fleetmap-web --config " + instance_home() +
                            "/fleetmap.conf --http-port 0 --log-level debug " + flags + " >>" + log_ + " 2>&1";
    pid_ = fork();
    if (pid_ == 0) {
      execl("/bin/sh", "sh", "-c", cmd.c_str(), static_cast<char*>(nullptr));
      _exit(127);
    }
    const std::string marker = "fleetmap-web: listening on ";
    const bool up = wait_until(
        [&] {
          const std::string text = read_file(log_);
          const size_t at = text.find(marker);
          if (at == std::string::npos) return exited();
          const size_t colon = text.find(':', text.find("//", at) + 2);
          port_ = static_cast<unsigned short>(std::stoi(text.substr(colon + 1)));
          return true;
        },
        15s);
    if (!up || port_ == 0) throw std::runtime_error("fleetmap-web did not start:\n" + read_file(log_));
  }
  ~WebProcess() { stop(); }
  // SIGTERM; the exit code (-1 when it did not exit by itself).
  int stop() {
    if (pid_ <= 0) return status_;
    ::kill(pid_, SIGTERM);
    int st = 0;
    waitpid(pid_, &st, 0);
    pid_ = -1;
    status_ = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
    return status_;
  }
  unsigned short port() const { return port_; }
  std::string log() const { return read_file(log_); }

 private:
  bool exited() {
    int st = 0;
    if (waitpid(pid_, &st, WNOHANG) != pid_) return false;
    pid_ = -1;
    return true;
  }
  std::string log_;
  pid_t pid_ = -1;
  int status_ = -1;
  unsigned short port_ = 0;
};

class WebHttp : public ::testing::Test {
 protected:
  void SetUp() override { web_ = std::make_unique<WebProcess>(flags()); }
  void TearDown() override {
    if (HasFailure() && web_) std::cerr << "fleetmap-web log:\n" << web_->log().substr(0, 20000);
  }
  virtual std::string flags() { return ""; }
  WebClient client() { return WebClient("127.0.0.1", web_->port()); }
  static std::string password(Role r) { return settings(r).password; }
  WebClient signed_in(Role r) {
    WebClient c = client();
    const WebResponse res = c.login(settings(r).user, password(r));
    EXPECT_EQ(res.status, 200) << res.body;
    return c;
  }
  std::unique_ptr<WebProcess> web_;
};

TEST_F(WebHttp, OperatorAndInspectorSignIn) {
  WebClient op = client();
  WebResponse r = op.login(settings(Role::Operator).user, password(Role::Operator));
  ASSERT_EQ(r.status, 200) << r.body;
  EXPECT_EQ(r.json()["role"], "operator");
  EXPECT_EQ(r.json()["csrf"].get<std::string>().size(), 64u);
  EXPECT_EQ(op.cookie.size(), 64u);
  const std::string set_cookie = r.header("set-cookie");
  EXPECT_NE(set_cookie.find("HttpOnly"), std::string::npos) << set_cookie;
  EXPECT_NE(set_cookie.find("SameSite=Strict"), std::string::npos) << set_cookie;
  EXPECT_EQ(set_cookie.find("Secure"), std::string::npos) << "plain HTTP: " << set_cookie;
  EXPECT_EQ(r.header("cache-control"), "no-store");

  r = op.get("/api/session");
  ASSERT_EQ(r.status, 200);
  EXPECT_EQ(r.json()["user"], settings(Role::Operator).user);
  EXPECT_EQ(r.json()["role"], "operator");
  EXPECT_EQ(r.json()["csrf"], op.csrf);

  WebClient insp = signed_in(Role::Inspector);
  r = insp.get("/api/session");
  ASSERT_EQ(r.status, 200);
  EXPECT_EQ(r.json()["role"], "inspector");
  EXPECT_NE(insp.cookie, op.cookie);
  EXPECT_NE(insp.csrf, op.csrf);
}

TEST_F(WebHttp, RefusesOtherAccountsAndWrongPasswords) {
  ensure_example_map("web_map");
  const std::string robot_pw = add_robot("web_r0", "web_map");
  WebClient c = client();
  WebResponse r = c.login("web_r0", robot_pw);
  EXPECT_EQ(r.status, 403) << r.body;
  EXPECT_EQ(r.json()["error"]["code"], "forbidden");
  EXPECT_TRUE(c.cookie.empty());
  // The server's account and the web program's own cannot sign in either.
  EXPECT_EQ(c.login(settings(Role::Server).user, password(Role::Server)).status, 403);
  EXPECT_EQ(c.login(settings(Role::Web).user, password(Role::Web)).status, 403);

  r = c.login(settings(Role::Operator).user, "not-the-password");
  EXPECT_EQ(r.status, 401) << r.body;
  EXPECT_EQ(r.json()["error"]["status"], 401);
  EXPECT_TRUE(c.cookie.empty());
  EXPECT_EQ(c.login("nobody_at_all", "whatever").status, 401);
  // The log names the user, never the password.
  EXPECT_EQ(web_->log().find("not-the-password"), std::string::npos);
  EXPECT_NE(web_->log().find("nobody_at_all"), std::string::npos);
  // The robot's connection was closed: no session of it lingers in the database.
  EXPECT_TRUE(wait_until([] { return scalar("SELECT COUNT(*) FROM information_schema.PROCESSLIST WHERE USER = 'web_r0'") == 0; }, 5s));
}

TEST_F(WebHttp, FiveFailedLoginsThrottleTheAddress) {
  WebClient c = client();
  for (int i = 0; i < 5; ++i) EXPECT_EQ(c.login(settings(Role::Operator).user, "wrong").status, 401);
  WebResponse r = c.login(settings(Role::Operator).user, password(Role::Operator));
  EXPECT_EQ(r.status, 429) << "even the right password, for a minute: " << r.body;
  EXPECT_EQ(r.header("retry-after"), "60");
}

TEST_F(WebHttp, SessionsCsrfAndRoles) {
  WebClient op = signed_in(Role::Operator);
  const json goal = {{"x", 1}, {"y", 2}};
  // A write without the token: 403 before any handler runs.
  WebResponse r = op.request("POST", "/api/robots/web_r0/goal", goal.dump(), {{"Content-Type", "application/json"}}, false);
  EXPECT_EQ(r.status, 403) << r.body;
  EXPECT_EQ(r.json()["error"]["code"], "csrf");
  r = op.request("POST", "/api/logout", "", {{"X-CSRF-Token", std::string(64, '0')}}, false);
  EXPECT_EQ(r.status, 403) << "a token of the right shape but not this session's";

  // A forged cookie is no session.
  WebClient forged = client();
  forged.cookie = std::string(64, 'a');
  forged.csrf = std::string(64, 'b');
  EXPECT_EQ(forged.get("/api/session").status, 401);
  EXPECT_EQ(forged.post("/api/robots/web_r0/goal", goal).status, 401);

  // An inspector's write: 403, token or not.
  WebClient insp = signed_in(Role::Inspector);
  r = insp.post("/api/robots/web_r0/goal", goal);
  EXPECT_EQ(r.status, 403) << r.body;
  EXPECT_EQ(r.json()["error"]["code"], "forbidden");

  // Logout ends the session; the cookie is cleared and no longer works.
  r = op.request("POST", "/api/logout");
  EXPECT_EQ(r.status, 200) << r.body;
  EXPECT_NE(r.header("set-cookie").find("Max-Age=0"), std::string::npos);
  EXPECT_EQ(op.cookie, "");  // the jar took the cleared cookie
  EXPECT_EQ(insp.get("/api/session").status, 200) << "another person's session is untouched";
}

TEST_F(WebHttp, LogoutInvalidatesTheOldCookie) {
  WebClient op = signed_in(Role::Operator);
  const std::string old_cookie = op.cookie;
  ASSERT_EQ(op.request("POST", "/api/logout").status, 200);
  WebClient replay = client();
  replay.cookie = old_cookie;
  EXPECT_EQ(replay.get("/api/session").status, 401);
}

TEST_F(WebHttp, BodiesLimitsAndErrors) {
  WebClient c = client();
  WebResponse r = c.request("POST", "/api/login", "{\"user\": ", {{"Content-Type", "application/json"}});
  EXPECT_EQ(r.status, 400);
  EXPECT_EQ(r.json()["error"]["code"], "bad_input");
  r = c.request("POST", "/api/login", "{}", {{"Content-Type", "text/plain"}});
  EXPECT_EQ(r.status, 415);
  r = c.request("POST", "/api/login", "{\"user\": \"" + std::string(70000, 'a') + "\"}", {{"Content-Type", "application/json"}});
  EXPECT_EQ(r.status, 413) << r.body;
  EXPECT_EQ(r.json()["error"]["code"], "payload_too_large");
  EXPECT_EQ(c.raw("GET / HTTP/1.1\r\nHost: x\r\nX-Big: " + std::string(9000, 'a') + "\r\n\r\n").substr(0, 12), "HTTP/1.1 431");
  EXPECT_EQ(c.get("/api/login").status, 405);
  WebClient op = signed_in(Role::Operator);
  EXPECT_EQ(op.get("/api/no/such/endpoint").status, 404);
  // Bad JSON on a route: 400 from the transport, before the handler.
  r = op.request("POST", "/api/robots/web_r0/goal", "{oops", {{"Content-Type", "application/json"}});
  EXPECT_EQ(r.status, 400) << r.body;
  // The server is still there for the next one.
  EXPECT_EQ(op.get("/api/session").status, 200);
}

TEST_F(WebHttp, KeepAliveServesTwoRequestsOnOneConnection) {
  WebClient c = client();
  const std::string two = "GET /api/session HTTP/1.1\r\nHost: x\r\n\r\nGET /api/session HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n";
  const std::string out = c.raw(two);
  size_t n = 0;
  for (size_t at = out.find("HTTP/1.1 401"); at != std::string::npos; at = out.find("HTTP/1.1 401", at + 1)) ++n;
  EXPECT_EQ(n, 2u) << out;
}

TEST_F(WebHttp, StaticFilesStayInTheirFolders) {
  WebClient c = client();
  for (const std::string target : {"/leaflet/../../../../etc/passwd", "/leaflet/%2e%2e/%2e%2e/%2e%2e/%2e%2e/etc/passwd",
                                   "/console/../../../../../etc/passwd", "/..%2f..%2f..%2f..%2fetc%2fpasswd"}) {
    const std::string out = c.raw("GET " + target + " HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n");
    EXPECT_TRUE(out.rfind("HTTP/1.1 404", 0) == 0 || out.rfind("HTTP/1.1 400", 0) == 0) << target << ":\n" << out;
    EXPECT_EQ(out.find("root:"), std::string::npos) << target;
  }
  if (std::filesystem::exists("/usr/share/javascript/leaflet/leaflet.js")) {
    WebResponse r = c.get("/leaflet/leaflet.js");
    EXPECT_EQ(r.status, 200);
    EXPECT_EQ(r.header("content-type"), "text/javascript; charset=utf-8");
    EXPECT_EQ(r.header("x-content-type-options"), "nosniff");
  }
}

class WebStatic : public WebHttp {
 protected:
  std::string flags() override {
    dir_ = temp_path("web_static");
    std::filesystem::create_directories(dir_ + "/js");
    write_file(dir_ + "/index.html", "<!doctype html><title>fleetmap</title>");
    write_file(dir_ + "/js/app.js", "console.log(1);");
    write_file(temp_path("web_openapi.json"), R"({"openapi": "3.0.3"})");
    return "--static-dir " + dir_ + " --openapi-file " + temp_path("web_openapi.json");
  }
  std::string dir_;
};

TEST_F(WebStatic, ServesTheConsoleWithItsHeaders) {
  WebClient c = client();
  WebResponse r = c.get("/");
  ASSERT_EQ(r.status, 200);
  EXPECT_EQ(r.body, "<!doctype html><title>fleetmap</title>");
  EXPECT_EQ(r.header("content-type"), "text/html; charset=utf-8");
  EXPECT_EQ(r.header("content-security-policy"), "default-src 'self'; img-src 'self' data:; style-src 'self' 'unsafe-inline'");
  EXPECT_EQ(r.header("x-content-type-options"), "nosniff");
  EXPECT_EQ(c.get("/js/app.js").header("content-type"), "text/javascript; charset=utf-8");
  EXPECT_EQ(c.get("/console/js/app.js").body, "console.log(1);");
  EXPECT_EQ(c.get("/js/none.js").status, 404);
  r = c.get("/api/openapi.json");
  ASSERT_EQ(r.status, 200);
  EXPECT_EQ(r.json()["openapi"], "3.0.3");
}

// A robot of the test's own: Ready through the real server, then SendPos.
class WebFeed : public WebHttp {
 protected:
  void SetUp() override {
    ensure_example_map("web_map");
    // Georeferenced, so that states carry lonlat: the map origin at 45.7 N, 4.8 E.
    const RunResult g = run("fleetmap", "map georef web_map 45.7 4.8");
    ASSERT_EQ(g.exit_code, 0) << g.err;
    robot_pw_ = add_robot("web_r1", "web_map");
    server_ = std::make_unique<ServerProcess>(kQuietRobotFlags, "web_server.log");
    robot_ = std::make_unique<SqlRobot>("web_r1", robot_pw_);
    robot_->send("Ready", R"({"magic": 7})");
    ASSERT_EQ(robot_->receive(2).size(), 2u);
    WebHttp::SetUp();
  }
  void TearDown() override {
    WebHttp::TearDown();
    server_.reset();
  }
  // Messages until one satisfies pred (true) or the timeout passes.
  template <class Pred>
  static bool until_message(FeedClient& f, Pred pred, std::chrono::milliseconds timeout = 10s) {
    const auto end = std::chrono::steady_clock::now() + timeout;
    while (std::chrono::steady_clock::now() < end) {
      auto m = f.next(std::chrono::duration_cast<std::chrono::milliseconds>(end - std::chrono::steady_clock::now()));
      if (!m) return false;
      if (pred(*m)) return true;
    }
    return false;
  }
  static const json* robot_in(const json& m, const std::string& name) {
    if (m.value("type", "") != "robots") return nullptr;
    for (const auto& r : m["robots"])
      if (r["name"] == name) return &r;
    return nullptr;
  }
  std::string robot_pw_;
  std::unique_ptr<ServerProcess> server_;
  std::unique_ptr<SqlRobot> robot_;
};

TEST_F(WebFeed, NeedsASessionAndThisOrigin) {
  WebClient c = client();
  try {
    FeedClient f(c, "");
    FAIL() << "a feed without a session";
  } catch (const WsRefused& e) {
    EXPECT_EQ(e.status, 401) << e.what();
  }
  try {
    FeedClient f(c, std::string(64, 'f'));
    FAIL() << "a feed with a forged cookie";
  } catch (const WsRefused& e) {
    EXPECT_EQ(e.status, 401) << e.what();
  }
  WebClient op = signed_in(Role::Operator);
  try {
    FeedClient f(op, op.cookie, "http://evil.example");
    FAIL() << "another site's page opening the feed with the cookie";
  } catch (const WsRefused& e) {
    EXPECT_EQ(e.status, 403) << e.what();
  }
  FeedClient ok(op, op.cookie, "http://127.0.0.1:" + std::to_string(web_->port()));
  auto hello = ok.next();
  ASSERT_TRUE(hello);
  EXPECT_EQ((*hello)["type"], "hello");
}

TEST_F(WebFeed, HelloEveryRobotThenARobotsMove) {
  WebClient insp = signed_in(Role::Inspector);
  FeedClient feed(insp, insp.cookie);
  auto hello = feed.next();
  ASSERT_TRUE(hello);
  EXPECT_EQ(*hello, (json{{"type", "hello"}, {"user", settings(Role::Inspector).user}, {"role", "inspector"}}));
  auto first = feed.next();
  ASSERT_TRUE(first);
  ASSERT_EQ((*first)["type"], "robots");
  const json* r1 = robot_in(*first, "web_r1");
  ASSERT_NE(r1, nullptr) << "the first robots message holds every robot: " << first->dump();
  EXPECT_EQ((*r1)["map"], "web_map");
  for (const char* key : {"state", "x", "y", "theta", "v", "lonlat", "task", "goal", "last_seen"})
    EXPECT_TRUE(r1->contains(key)) << key << " in " << r1->dump();

  robot_->send("SendPos", R"({"x": 3.25, "y": 4.5, "theta": 0.5, "v": 0.2})");
  json moved;
  ASSERT_TRUE(until_message(feed, [&](const json& m) {
    const json* r = robot_in(m, "web_r1");
    if (!r || !(*r)["x"].is_number() || (*r)["x"] != 3.25) return false;
    moved = *r;
    return true;
  })) << web_->log().substr(0, 5000);
  EXPECT_EQ(moved["y"], 4.5);
  EXPECT_EQ(moved["theta"], 0.5);
  EXPECT_EQ(moved["state"], "moving");
  // 3.25 m east and 4.5 m north of the origin: about 4.2e-5 degrees of longitude and
  // 4.0e-5 of latitude.
  ASSERT_TRUE(moved["lonlat"].is_array()) << moved.dump();
  EXPECT_NEAR(moved["lonlat"][0].get<double>(), 4.8 + 3.25 / (111320 * std::cos(45.7 * M_PI / 180)), 1e-6);
  EXPECT_NEAR(moved["lonlat"][1].get<double>(), 45.7 + 4.5 / 111132, 1e-6);
  const std::string seen = moved["last_seen"];
  EXPECT_EQ(seen.size() >= 20 ? seen.substr(10, 1) + seen.substr(seen.size() - 1) : seen, "TZ") << seen;
}

TEST_F(WebFeed, ANewTaskArrivesAsATasksMessage) {
  WebClient op = signed_in(Role::Operator);
  FeedClient feed(op, op.cookie);
  ASSERT_TRUE(feed.next());  // hello
  ASSERT_TRUE(feed.next());  // every robot
  auto c = connect_as(Role::Operator);
  const unsigned long long task = FleetStore(*c).assign_goal("web_r1", 5, 6);
  json got;
  ASSERT_TRUE(until_message(feed, [&](const json& m) {
    if (m.value("type", "") != "tasks") return false;
    for (const auto& t : m["tasks"])
      if (t["id"] == task) got = t;
    return !got.is_null();
  }));
  EXPECT_EQ(got["robot"], "web_r1");
  EXPECT_EQ(got["goal"], json::array({5, 6}));
  for (const char* key : {"state", "created_at", "updated_at", "reason"}) EXPECT_TRUE(got.contains(key)) << key;
}

// The kernel's queues of the IPv4 loopback connection from port `from` to port `to`
// (/proc/net/tcp): bytes written but not yet taken by the peer, and bytes received but
// not yet read; {-1, -1} when there is no such connection.
struct SocketQueues {
  long long unsent = -1, unread = -1;
};
SocketQueues socket_queues(unsigned short from, unsigned short to) {
  std::istringstream in(read_file("/proc/net/tcp"));
  std::string line;
  std::getline(in, line);  // the header
  char want_local[16], want_remote[16];
  std::snprintf(want_local, sizeof want_local, ":%04X", from);
  std::snprintf(want_remote, sizeof want_remote, ":%04X", to);
  while (std::getline(in, line)) {
    std::istringstream f(line);
    std::string slot, local, remote, state, queues;
    f >> slot >> local >> remote >> state >> queues;
    if (local.size() >= 5 && remote.size() >= 5 && local.substr(local.size() - 5) == want_local &&
        remote.substr(remote.size() - 5) == want_remote)
      return {std::stoll(queues.substr(0, queues.find(':')), nullptr, 16),
              std::stoll(queues.substr(queues.find(':') + 1), nullptr, 16)};
  }
  return {};
}

TEST_F(WebFeed, AClientThatNeverReadsDoesNotStallAnother) {
  // Eight robots moving at once: frames of a few KiB every feed period, more than the
  // stalled client's socket buffers hold within the test.
  std::vector<std::unique_ptr<SqlRobot>> fleet;
  for (int k = 0; k < 8; ++k) {
    const std::string name = "web_s" + std::to_string(k);
    fleet.push_back(std::make_unique<SqlRobot>(name, add_robot(name, "web_map")));
    fleet.back()->send("Ready", R"({"magic": 7})");
    ASSERT_EQ(fleet.back()->receive(2).size(), 2u) << name;
  }
  WebClient op = signed_in(Role::Operator);
  FeedClient stalled(op, op.cookie, "", 2048);  // never read
  FeedClient reader(op, op.cookie);
  ASSERT_TRUE(reader.next());  // hello
  ASSERT_TRUE(reader.next());  // every robot
  std::set<double> seen;
  size_t reader_bytes = 0;
  double x = 0, reader_x = 0;  // the last move sent, and the last of web_s7's the reader got
  const auto started = std::chrono::steady_clock::now();
  for (int i = 1; i <= 200; ++i) {
    x = 1 + 0.01 * i;
    for (auto& r : fleet) r->send("SendPos", json{{"x", x}, {"y", 2.0}, {"theta", 0.0}, {"v", 0.3}}.dump());
    std::this_thread::sleep_for(25ms);
    while (auto m = reader.next(1ms)) {
      reader_bytes += m->dump().size();
      if (const json* r = robot_in(*m, "web_s0"); r && (*r)["x"].is_number()) seen.insert((*r)["x"].get<double>());
      if (const json* r = robot_in(*m, "web_s7"); r && (*r)["x"].is_number()) reader_x = (*r)["x"].get<double>();
    }
  }
  // The last move may have come while the loop read; if not, it must come now (nothing
  // else changes: the robots stay silent but not lost, kQuietRobotFlags).
  const auto is_last = [&](double got) { return std::abs(got - x) < 1e-9; };
  ASSERT_TRUE(is_last(reader_x) || until_message(reader, [&](const json& m) {
    const json* r = robot_in(m, "web_s7");
    return r && (*r)["x"].is_number() && is_last((*r)["x"].get<double>());
  }, 5s)) << "the last move never reached the reading client";
  EXPECT_LT(std::chrono::steady_clock::now() - started, 60s);
  EXPECT_GE(seen.size(), 40u) << "the reading client got a fresh state about every feed period";
  // What the server wrote towards the stalled client is all still in the kernel's
  // queues (it read nothing), and it is much less than what the reader got: the
  // server's write to it stopped completing and the rest was coalesced, not queued.
  const SocketQueues server_side = socket_queues(web_->port(), stalled.local_port());
  const SocketQueues client_side = socket_queues(stalled.local_port(), web_->port());
  ASSERT_GE(server_side.unsent, 0);
  ASSERT_GE(client_side.unread, 0);
  EXPECT_LT(static_cast<size_t>(server_side.unsent + client_side.unread), reader_bytes / 2)
      << "reader got " << reader_bytes << " bytes; towards the stalled client: " << server_side.unsent
      << " unsent, " << client_side.unread << " unread";
  // When it reads at last, it gets what the kernel held and then the latest state of
  // every robot at once: far less than the reader got, ending with the last move. A
  // server that queued every frame for it would send it all of them now.
  size_t stalled_bytes = 0, stalled_frames = 0;
  std::map<std::string, double> last_x;
  while (auto m = stalled.next(2s)) {
    stalled_bytes += m->dump().size();
    ++stalled_frames;
    if (m->value("type", "") == "robots")
      for (const auto& r : (*m)["robots"])
        if (r["x"].is_number()) last_x[r["name"]] = r["x"];
    bool all_latest = true;
    for (int k = 0; k < 8; ++k) {
      auto it = last_x.find("web_s" + std::to_string(k));
      all_latest = all_latest && it != last_x.end() && std::abs(it->second - x) < 1e-9;
    }
    if (all_latest) break;
  }
  for (int k = 0; k < 8; ++k) EXPECT_NEAR(last_x["web_s" + std::to_string(k)], x, 1e-9) << "web_s" << k;
  EXPECT_LT(stalled_bytes, reader_bytes / 2) << stalled_frames << " frames after the stall; the reader got "
                                             << reader_bytes << " bytes";
  EXPECT_EQ(op.get("/api/session").status, 200);
}

// A self-signed certificate made with the openssl CLI.
class WebTls : public WebFeed {
 protected:
  std::string flags() override {
    const std::string cert = temp_path("web_cert.pem"), key = temp_path("web_key.pem");
    const std::string cmd = "openssl req -x509 -newkey rsa:2048 -nodes -keyout " + key + " -out " + cert +
                            " -days 1 -subj /CN=127.0.0.1 >/dev/null 2>&1";
    if (std::system(cmd.c_str()) != 0) throw std::runtime_error("openssl req failed");
    return "--tls-cert " + cert + " --tls-key " + key;
  }
};

TEST_F(WebTls, HttpsLoginSecureCookieAndWss) {
  WebClient c("127.0.0.1", web_->port(), true);
  WebResponse r = c.login(settings(Role::Operator).user, password(Role::Operator));
  ASSERT_EQ(r.status, 200) << r.body;
  EXPECT_NE(r.header("set-cookie").find("; Secure"), std::string::npos) << r.header("set-cookie");
  EXPECT_EQ(c.get("/api/session").json()["role"], "operator");
  FeedClient feed(c, c.cookie, "https://127.0.0.1:" + std::to_string(web_->port()));
  auto hello = feed.next();
  ASSERT_TRUE(hello);
  EXPECT_EQ((*hello)["type"], "hello");
  // Plain HTTP on the TLS port gets no answer in HTTP.
  WebClient plain("127.0.0.1", web_->port());
  EXPECT_EQ(plain.raw("GET /api/session HTTP/1.1\r\nHost: x\r\n\r\n", 3s).find("HTTP/1.1 200"), std::string::npos);
}

TEST(WebProgram, ExitCodes) {
  const std::string conf = "--config " + instance_home() + "/fleetmap.conf";
  EXPECT_EQ(run("fleetmap-web", "--help").exit_code, 0);
  RunResult r = run("fleetmap-web", conf + " --http-port 80x");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("http_port"), std::string::npos) << r.err;
  r = run("fleetmap-web", conf + " --tls-cert /tmp/only-one.pem");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  r = run("fleetmap-web", conf + " --socket /nonexistent/mysqld.sock");
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find("cannot connect"), std::string::npos) << r.err;
}

TEST(WebProgram, StopsCleanlyOnSigterm) {
  WebProcess web;
  WebClient c("127.0.0.1", web.port());
  EXPECT_EQ(c.login(settings(Role::Operator).user, settings(Role::Operator).password).status, 200);
  FeedClient feed(c, c.cookie);
  ASSERT_TRUE(feed.next());
  EXPECT_EQ(web.stop(), 0) << web.log();
}

}  // namespace
}  // namespace fleetmap::test
