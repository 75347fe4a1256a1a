// The console (server/web/console, docs/console.md) in a real browser: headless Chromium
// driven over the DevTools protocol (cdp_client.h) against the real fleetmap-web, the real
// fleetmap-server and simulated robots (fleetmap-robot) on the example campus. The page is
// used as a person would: typing into the login form, clicking rows, buttons and the map.
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <regex>
#include <thread>

#include <gtest/gtest.h>

#include "tests/integration/cdp_client.h"
#include "tests/integration/server_fixture.h"
#include "tests/integration/test_db.h"

namespace fleetmap::test {
namespace {

using namespace std::chrono_literals;
using nlohmann::json;

const std::string kMap = "console_campus";  // maps/example-campus.map: 60 m x 40 m, open lanes

// A child process running `sh -c "exec COMMAND"`, ended with SIGTERM.
class Child {
 public:
  explicit Child(const std::string& command) {
    pid_ = fork();
    if (pid_ == 0) {
      execl("/bin/sh", "sh", "-c", ("exec " + command).c_str(), static_cast<char*>(nullptr));
      _exit(127);
    }
    if (pid_ < 0) throw std::runtime_error("fork failed");
  }
  ~Child() {
    ::kill(pid_, SIGTERM);
    int status = 0;
    waitpid(pid_, &status, 0);
  }
  bool exited() {
    int status = 0;
    return waitpid(pid_, &status, WNOHANG) == pid_;
  }
  Child(const Child&) = delete;
  Child& operator=(const Child&) = delete;

 private:
  pid_t pid_ = -1;
};

// fleetmap-web on a free port (--http-port 0: it prints the address it listens on).
class WebProcess {
 public:
  WebProcess() : log_(temp_path("console_web.log")) {
    write_file(log_, "");
    child_ = std::make_unique<Child>(std::string(FLEETMAP_BIN_DIR) + "/fleetmap-web --config " +
                                     std::getenv("FLEETMAP_CONFIG") + " --http-port 0 --log-level debug >" + log_ +
                                     " 2>&1");
    // Its first line on stdout (docs/web-api.md "Running it").
    const std::regex address(R"(fleetmap-web: listening on https?://[^\s/]+:(\d+)/)");
    for (int i = 0; i < 200 && port_ == 0; ++i) {
      std::smatch m;
      const std::string out = read_file(log_);
      if (std::regex_search(out, m, address)) port_ = std::stoi(m[1]);
      else if (child_->exited()) break;
      else std::this_thread::sleep_for(50ms);
    }
    if (port_ == 0) throw std::runtime_error("fleetmap-web printed no address; its output:\n" + read_file(log_));
  }
  std::string url() const { return "http://127.0.0.1:" + std::to_string(port_); }
  std::string log() const { return read_file(log_); }

 private:
  std::string log_;
  std::unique_ptr<Child> child_;
  int port_ = 0;
};

// fleetmap-robot, the simulated robot, on its own account (fleet_end_to_end_test.cpp).
std::unique_ptr<Child> start_robot(const std::string& name, const std::string& start, int seed) {
  return std::make_unique<Child>(std::string(FLEETMAP_BIN_DIR) + "/fleetmap-robot --config " +
                                 std::getenv("FLEETMAP_CONFIG") + " --user " + name + " --password-file " +
                                 temp_path(name + ".pw") + " --start " + start +
                                 " --speed 1.5 --tracking-particles 500 --seed " + std::to_string(seed) + " >" +
                                 temp_path(name + ".log") + " 2>&1");
}

std::string quoted(const std::string& s) { return json(s).dump(); }

// The newest task of a robot in the database: {id, state, goal x, goal y}.
struct TaskRow {
  long long id = 0;
  std::string state;
  double gx = 0, gy = 0;
};
TaskRow newest_task(const std::string& robot) {
  auto c = admin();
  mysqlpp::Query q = c->query();
  q << "SELECT t.id, t.state, t.goal_x, t.goal_y FROM tasks t JOIN robots r ON r.id = t.robot_id WHERE r.db_user = "
    << mysqlpp::quote << robot << " ORDER BY t.id DESC LIMIT 1";
  auto r = q.store();
  if (r.empty()) return {};
  return {static_cast<long long>(r[0][0]), std::string(r[0][1]), static_cast<double>(r[0][2]),
          static_cast<double>(r[0][3])};
}

long long task_count() { return scalar("SELECT COUNT(*) FROM tasks"); }

class ConsoleBrowser : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    ensure_example_map(kMap);
    // One object, a crate tagged box off the robots' lanes, whose id is markup.
    const std::string scene = temp_path("console_scene.geojson");
    write_file(scene, R"({"type":"FeatureCollection","fleetmap":{"frame":"map","units":"m"},"features":[
{"type":"Feature","properties":{"kind":"object","id":"<img src=x onerror=window.injected=1>crate","tag":"box",
 "z":[[0,0.5]]},
 "geometry":{"type":"Polygon","coordinates":[[[24,30],[27,30],[27,32],[24,32],[24,30]]]}}]})");
    const RunResult imported = run("fleetmap", "objects import " + kMap + " " + scene + " --replace --add-tags");
    if (imported.exit_code != 0) throw std::runtime_error("objects import: " + imported.err);
  }
  // Before any robot or server is started: a missing browser is said at once.
  void SetUp() override {
    ASSERT_FALSE(Chromium::find_executable().empty())
        << "chromium is not installed (no chromium or chromium-browser on PATH, FLEETMAP_CHROMIUM unset): "
           "run scripts/setup.sh, which installs it";
  }
  // The page threw nothing and logged no error while the test used it.
  void TearDown() override {
    if (page_) {
      EXPECT_EQ(page_->page_errors(), "");
    }
    if (HasFailure() && web_) std::cerr << "fleetmap-web log:\n" << web_->log().substr(0, 20000);
  }

  void open_browser() {
    browser_ = std::make_unique<Chromium>(temp_path("console_chromium.log"));
    page_ = std::make_unique<CdpPage>(browser_->port());
    // 1280x800 CSS pixels whatever the headless window is: the screenshot's size.
    page_->call("Emulation.setDeviceMetricsOverride",
                {{"width", 1280}, {"height", 800}, {"deviceScaleFactor", 1}, {"mobile", false}});
  }

  // Through the form, as a person: click each field, type, click "Sign in".
  void sign_in(Role role, const std::string& map = kMap) {
    const DbSettings s = settings(role);
    page_->navigate(web_->url() + "/?map=" + map);
    ASSERT_TRUE(page_->wait_for("!document.getElementById('login').hidden", 10s)) << web_->log();
    page_->click_element("#login-user");
    page_->insert_text(s.user);
    page_->click_element("#login-password");
    page_->insert_text(s.password);
    page_->click_element("#login-submit");
    ASSERT_TRUE(page_->wait_for("document.getElementById('login').hidden && window.fleetmapConsole.session", 10s))
        << text("#login-error") << "\n" << web_->log();
    EXPECT_EQ(text("#who-user"), s.user);
    ASSERT_TRUE(page_->wait_for("document.getElementById('map-select').value === " + quoted(map), 10s));
  }

  std::string text(const std::string& selector) {
    const json t = page_->evaluate("(() => { const e = document.querySelector(" + quoted(selector) +
                                   "); return e ? e.textContent : null; })()");
    return t.is_string() ? t.get<std::string>() : "";
  }

  bool visible(const std::string& selector) {
    return page_->evaluate("(() => { const e = document.querySelector(" + quoted(selector) +
                           "); return Boolean(e && e.getClientRects().length > 0 && getComputedStyle(e).visibility !== 'hidden'); })()") == true;
  }

  // A real click on the map at map-frame (x, y): the page says where that is on screen.
  void click_map(double x, double y) {
    const json at = page_->evaluate("(() => { const p = fleetmapConsole.toContainerPoint(" + std::to_string(x) + ", " +
                                    std::to_string(y) + "); const r = document.getElementById('map').getBoundingClientRect();"
                                    " return [p.x + r.left, p.y + r.top]; })()");
    ASSERT_TRUE(at.is_array()) << at.dump();
    page_->click(at[0].get<double>(), at[1].get<double>());
  }

  // Records every state each task row takes, from now on (the feed may pass through
  // "active" faster than a poll).
  void watch_task_rows() {
    page_->evaluate(
        "window.seenStates = {}; new MutationObserver((list) => { for (const m of list) {"
        " const rows = m.type === 'attributes' ? [m.target] : Array.from(m.addedNodes);"
        " for (const r of rows) if (r.dataset && r.dataset.task) {"
        "  const s = (window.seenStates[r.dataset.task] = window.seenStates[r.dataset.task] || []);"
        "  if (s[s.length - 1] !== r.dataset.state) s.push(r.dataset.state); } } })"
        ".observe(document.getElementById('tasks'), {subtree: true, childList: true, attributes: true,"
        " attributeFilter: ['data-state']}); true");
  }

  void screenshot_if_asked() {
    const char* path = std::getenv("FLEETMAP_SCREENSHOT");
    if (!path || !*path) return;
    write_file(path, page_->screenshot_png());
  }

  std::unique_ptr<WebProcess> web_;
  std::unique_ptr<Chromium> browser_;
  std::unique_ptr<CdpPage> page_;
};

TEST_F(ConsoleBrowser, OperatorWatchesRobotsGivesAGoalByClickAbortsAndSeesARefusal) {
  // name, true start pose (= operator's initial pose)
  const struct {
    std::string name, start;
  } robots[] = {{"console_r1", "5 22 0"}, {"console_r2", "10 5 0"}, {"console_r3", "55 8 3.14159"}};
  for (const auto& r : robots) {
    add_robot(r.name, kMap);
    ASSERT_EQ(run("fleetmap", "pose-ini " + r.name + " " + r.start).exit_code, 0);
  }
  ServerProcess server("", "console_server.log");
  std::vector<std::unique_ptr<Child>> procs;
  int seed = 11;
  for (const auto& r : robots) procs.push_back(start_robot(r.name, r.start, seed++));
  ASSERT_TRUE(wait_until(
      [] {
        return scalar("SELECT COUNT(*) FROM robots WHERE db_user LIKE 'console_r%' AND removed_at IS NULL AND x IS NOT NULL "
                      "AND state = 'ready'") == 3;
      },
      40s, 100ms))
      << read_file(temp_path("console_r1.log"));
  // r1 drives along the lane y = 22 while we watch; r3 gets a long way to go along y = 8,
  // to be aborted on its way.
  ASSERT_EQ(run("fleetmap", "goal console_r1 35 22").exit_code, 0);
  ASSERT_EQ(run("fleetmap", "goal console_r3 4 8").exit_code, 0);  // 51 m: half a minute

  web_ = std::make_unique<WebProcess>();
  open_browser();
  sign_in(Role::Operator);
  EXPECT_EQ(text("#who-role"), "operator");
  EXPECT_TRUE(visible("#mode-goal"));

  // Live: every robot has a marker, and r1's moves between two reads.
  ASSERT_TRUE(page_->wait_for(
      "['console_r1', 'console_r2', 'console_r3'].every((n) => fleetmapConsole.markers[n] &&"
      " document.querySelector('#robots tr[data-robot=\"' + n + '\"]'))",
      15s))
      << web_->log();
  ASSERT_TRUE(page_->wait_for("fleetmapConsole.robots.console_r1.state === 'moving'", 15s));
  const std::string where = "(() => { const m = fleetmapConsole.markers.console_r1; const p = m.getLatLng();"
                            " return [p.lng, p.lat, Boolean(m.getElement() && m.getElement().isConnected)]; })()";
  const json p1 = page_->evaluate(where);
  std::this_thread::sleep_for(1500ms);
  const json p2 = page_->evaluate(where);
  EXPECT_TRUE(p1[2] == true && p2[2] == true) << "the marker is on the page";
  EXPECT_GT(std::hypot(p2[0].get<double>() - p1[0].get<double>(), p2[1].get<double>() - p1[1].get<double>()), 0.3)
      << p1.dump() << " then " << p2.dump();
  // Its arrow is coloured by state and turned by its heading (about 0 along +x).
  EXPECT_EQ(page_->evaluate("fleetmapConsole.markers.console_r1.getElement().querySelector('.arrow').classList"
                            ".contains('state-moving')"),
            true);

  watch_task_rows();
  // A goal by clicking the map for the idle r2: its row goes active, then done.
  const long long before = task_count();
  page_->click_element("#robots tr[data-robot=\"console_r2\"]");
  ASSERT_TRUE(page_->wait_for("!document.getElementById('mode-goal').disabled", 5s));
  page_->click_element("#mode-goal");
  click_map(20, 5);
  ASSERT_TRUE(wait_until([&] { return task_count() == before + 1; }, 10s)) << text("#message");
  const TaskRow goal = newest_task("console_r2");
  EXPECT_NEAR(goal.gx, 20, 0.3) << "the clicked pixel is the map-frame point";
  EXPECT_NEAR(goal.gy, 5, 0.3);
  const std::string row = "#tasks tr[data-task=\"" + std::to_string(goal.id) + "\"]";
  EXPECT_TRUE(page_->wait_for("document.querySelector(" + quoted(row) + ")", 10s)) << text("#message");
  EXPECT_TRUE(page_->wait_for("document.querySelector(" + quoted(row + "[data-state=\"done\"]") + ")", 60s))
      << newest_task("console_r2").state;
  const json seen = page_->evaluate("window.seenStates[" + quoted(std::to_string(goal.id)) + "] || []");
  EXPECT_NE(std::find(seen.begin(), seen.end(), "active"), seen.end()) << seen.dump();
  EXPECT_EQ(seen.back(), "done") << seen.dump();
  EXPECT_EQ(newest_task("console_r2").state, "done");

  // Abort r3's task with its row's button.
  const TaskRow r3 = newest_task("console_r3");
  ASSERT_NE(r3.state, "done") << "r3's goal was to take longer";
  const std::string r3row = "#tasks tr[data-task=\"" + std::to_string(r3.id) + "\"]";
  ASSERT_TRUE(page_->wait_for("document.querySelector(" + quoted(r3row + " button.abort") + ")", 10s));
  screenshot_if_asked();
  page_->click_element(r3row + " button.abort");
  EXPECT_TRUE(page_->wait_for("document.querySelector(" + quoted(r3row + "[data-state=\"aborted\"]") + ")", 30s))
      << text("#message") << " db: " << newest_task("console_r3").state;
  EXPECT_EQ(newest_task("console_r3").state, "aborted");
  EXPECT_FALSE(visible(r3row + " button.abort")) << "no abort button on a closed task";

  // A goal inside the library (a closed building, doors shut: accept_goal refuses it):
  // the refusal is shown at once, and no task exists.
  const long long rows = page_->evaluate("document.querySelectorAll('#tasks tr').length").get<long long>();
  const long long tasks = task_count();
  page_->click_element("#robots tr[data-robot=\"console_r2\"]");
  page_->click_element("#mode-goal");
  click_map(12, 30);
  ASSERT_TRUE(page_->wait_for("fleetmapConsole.lastError && fleetmapConsole.lastError.status === 422", 10s))
      << text("#message");
  EXPECT_EQ(page_->evaluate("fleetmapConsole.lastError.code"), "goal_refused");
  const std::string server_says = page_->evaluate("fleetmapConsole.lastError.message").get<std::string>();
  EXPECT_FALSE(server_says.empty());
  EXPECT_TRUE(visible("#message"));
  EXPECT_NE(text("#message").find(server_says), std::string::npos) << text("#message");
  EXPECT_EQ(page_->evaluate("document.getElementById('message').classList.contains('error')"), true);
  std::this_thread::sleep_for(1s);
  EXPECT_EQ(task_count(), tasks);
  EXPECT_EQ(page_->evaluate("document.querySelectorAll('#tasks tr').length").get<long long>(), rows);

  // Reopened (the session cookie still holds): r2, stopped at its goal, has its way from
  // x = 10 to 20 drawn from the recorded trajectory alone.
  page_->navigate(web_->url() + "/?map=" + kMap);
  const std::string trail = "fleetmapConsole.trails.console_r2";
  ASSERT_TRUE(page_->wait_for("fleetmapConsole.session && " + trail + " && " + trail + ".loaded", 15s))
      << page_->page_errors();
  EXPECT_TRUE(page_->evaluate("document.getElementById('login').hidden") == true) << "no second sign-in";
  const json span = page_->evaluate("(() => { const xs = " + trail + ".line.getLatLngs().flat().map((p) => p.lng);"
                                    " return [xs.length, Math.min(...xs), Math.max(...xs)]; })()");
  EXPECT_GT(span[0].get<int>(), 10) << span.dump();
  EXPECT_LT(span[1].get<double>(), 11.5) << span.dump();
  EXPECT_GT(span[2].get<double>(), 19) << span.dump();

  // A goal by meaning: near the object tagged box (the crate, 24..27 x 30..32).
  const long long before_tag = task_count();
  page_->click_element("#robots tr[data-robot=\"console_r2\"]");
  ASSERT_TRUE(page_->wait_for("!document.getElementById('goal-named-submit').disabled", 5s));
  page_->click_element("#goal-name");
  page_->insert_text("box");
  page_->click_element("#goal-named-submit");
  ASSERT_TRUE(wait_until([&] { return task_count() == before_tag + 1; }, 10s)) << text("#message");
  const TaskRow near = newest_task("console_r2");
  EXPECT_TRUE(near.gx > 22 && near.gx < 29 && near.gy > 28 && near.gy < 34) << near.gx << ", " << near.gy;
  EXPECT_TRUE(page_->wait_for("document.getElementById('message').textContent.indexOf('Task #" +
                              std::to_string(near.id) + "') === 0", 5s))
      << text("#message");
}

TEST_F(ConsoleBrowser, InspectorSeesNoWriteControlsAndAForcedWriteIsRefused) {
  // An open task to show: a robot with an initial pose and a goal, no robot process.
  add_robot("console_i1", kMap);
  ASSERT_EQ(run("fleetmap", "pose-ini console_i1 10 5 0").exit_code, 0);
  ASSERT_EQ(run("fleetmap", "goal console_i1 20 5").exit_code, 0);
  const TaskRow open = newest_task("console_i1");
  ASSERT_EQ(open.state, "assigned");

  web_ = std::make_unique<WebProcess>();
  open_browser();
  sign_in(Role::Inspector);
  EXPECT_EQ(text("#who-role"), "inspector");
  const std::string row = "#tasks tr[data-task=\"" + std::to_string(open.id) + "\"]";
  ASSERT_TRUE(page_->wait_for("document.querySelector(" + quoted(row) + ")", 10s));
  EXPECT_FALSE(visible("#mode-goal"));
  EXPECT_FALSE(visible("#mode-pose"));
  EXPECT_FALSE(visible("#goal-named"));
  EXPECT_EQ(page_->evaluate("document.querySelectorAll('#tasks button.abort').length"), 0);
  // The session cookie is HttpOnly: the page's scripts cannot read it (SPEC 4).
  EXPECT_EQ(page_->evaluate("document.cookie.indexOf('fleetmap_session')"), -1);

  // Forced: the page's own token on a write, straight through fetch, is refused by the server.
  const json status = page_->evaluate(
      "fetch('/api/robots/console_i1/abort', {method: 'POST', credentials: 'same-origin', headers: {"
      " 'Content-Type': 'application/json', 'X-CSRF-Token': fleetmapConsole.session.csrf}, body: '{}'})"
      ".then((r) => r.status)");
  EXPECT_EQ(status, 403);
  // And the page shows the server's 403 when its own abort is forced.
  page_->evaluate("abortTask(" + std::to_string(open.id) + ")");
  EXPECT_TRUE(page_->wait_for("fleetmapConsole.lastError && fleetmapConsole.lastError.status === 403", 5s));
  EXPECT_NE(text("#message").find("403"), std::string::npos) << text("#message");
  EXPECT_EQ(newest_task("console_i1").state, "assigned");
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM tasks WHERE id = " + std::to_string(open.id) + " AND abort_requested_at IS NOT NULL"), 0);

  // Names are data, shown as text: an object's id that is HTML stays text in its tooltip.
  ASSERT_TRUE(page_->wait_for("document.querySelector('#map path.layer-objects')", 10s));
  const json at = page_->evaluate("(() => { const p = fleetmapConsole.toContainerPoint(25.5, 31); const r ="
                                  " document.getElementById('map').getBoundingClientRect(); return [p.x + r.left, p.y + r.top]; })()");
  page_->call("Input.dispatchMouseEvent", {{"type", "mouseMoved"}, {"x", at[0]}, {"y", at[1]}});
  EXPECT_TRUE(page_->wait_for("document.querySelector('.leaflet-tooltip') &&"
                              " document.querySelector('.leaflet-tooltip').textContent.indexOf('<img') >= 0", 5s))
      << page_->evaluate("document.querySelector('.leaflet-tooltip') && document.querySelector('.leaflet-tooltip').outerHTML").dump();
  EXPECT_EQ(page_->evaluate("window.injected === undefined && !document.querySelector('.leaflet-tooltip img')"), true);

  // Log out: the form is back and the session is gone on the server too.
  page_->click_element("#logout");
  EXPECT_TRUE(page_->wait_for("!document.getElementById('login').hidden", 5s));
  EXPECT_EQ(page_->evaluate("fetch('/api/session', {credentials: 'same-origin'}).then((r) => r.status)"), 401);
}

// A georeferenced map in WGS 84 (Web Mercator, no tiles): the layers come in lon/lat, and
// a click still gives a goal in the map frame.
TEST_F(ConsoleBrowser, Wgs84ViewOfAGeoreferencedMapTakesGoalsAndPosesInTheMapFrame) {
  const std::string map = "console_geo";
  ensure_example_map(map);
  // The map's x axis 0.5 rad north of east, its origin in Zurich.
  ASSERT_EQ(run("fleetmap", "map georef " + map + " 47.3769 8.5417 --heading 0.5").exit_code, 0);
  add_robot("console_g1", map);  // no process: for a goal and a pose
  ASSERT_EQ(run("fleetmap", "pose-ini console_g1 10 5 0").exit_code, 0);
  add_robot("console_g2", map);  // live: drawn by its lonlat
  ASSERT_EQ(run("fleetmap", "pose-ini console_g2 10 22 0.3").exit_code, 0);
  ServerProcess server("", "console_geo_server.log");
  auto robot = start_robot("console_g2", "10 22 0.3", 7);
  ASSERT_TRUE(wait_until([] { return scalar("SELECT COUNT(*) FROM robots WHERE db_user = 'console_g2' AND removed_at IS NULL"
                                            " AND x IS NOT NULL") == 1; }, 40s, 100ms))
      << read_file(temp_path("console_g2.log"));

  web_ = std::make_unique<WebProcess>();
  open_browser();
  sign_in(Role::Operator, map);
  ASSERT_TRUE(page_->wait_for("!document.getElementById('crs-toggle').hidden", 5s)) << "a georeferenced map";
  page_->click_element("#crs-wgs84");
  ASSERT_TRUE(page_->wait_for("fleetmapConsole.frame === 'wgs84' && fleetmapConsole.wgs84Fit", 10s))
      << page_->page_errors();
  const json fit = page_->evaluate("fleetmapConsole.wgs84Fit");
  // An affine fit (frames.js): a similarity would leave 6 cm here, Web Mercator not being
  // quite conformal on the ellipsoid.
  EXPECT_LT(fit["residual"].get<double>(), 0.01) << fit.dump();
  // Web Mercator is north-up: the frame's rotation is the georeference's heading.
  EXPECT_NEAR(fit["rotation"].get<double>(), 0.5, 0.01) << fit.dump();
  EXPECT_EQ(page_->evaluate("fleetmapConsole.map.options.crs === L.CRS.EPSG3857"), true);

  // The live robot: its marker at the server's lonlat, which is where the fit puts its
  // map-frame x, y (within a pixel), its arrow turned by theta plus the frame's rotation.
  ASSERT_TRUE(page_->wait_for("fleetmapConsole.markers.console_g2 && fleetmapConsole.robots.console_g2.lonlat", 10s))
      << page_->evaluate("JSON.stringify(fleetmapConsole.robots.console_g2 || null)").dump();
  const json live = page_->evaluate(
      "(() => { const r = fleetmapConsole.robots.console_g2, m = fleetmapConsole.markers.console_g2;"
      " const a = fleetmapConsole.toContainerPoint(r.x, r.y), b = fleetmapConsole.map.latLngToContainerPoint(m.getLatLng());"
      " const turn = parseFloat(m.getElement().querySelector('.arrow').style.transform.replace('rotate(', ''));"
      " const want = -(r.theta + fleetmapConsole.wgs84Fit.rotation);"
      " const d = Math.atan2(Math.sin(turn - want), Math.cos(turn - want));"
      " return {px: Math.hypot(a.x - b.x, a.y - b.y), lonlat: m.getLatLng().lng === r.lonlat[0] &&"
      " m.getLatLng().lat === r.lonlat[1], heading: Math.abs(d)}; })()");
  EXPECT_LT(live["px"].get<double>(), 1.0) << live.dump();
  EXPECT_EQ(live["lonlat"], true) << live.dump();
  EXPECT_LT(live["heading"].get<double>(), 0.01) << live.dump();

  const long long before = task_count();
  page_->click_element("#robots tr[data-robot=\"console_g1\"]");
  ASSERT_TRUE(page_->wait_for("!document.getElementById('mode-goal').disabled", 5s));
  page_->click_element("#mode-goal");
  click_map(20, 5);
  ASSERT_TRUE(wait_until([&] { return task_count() == before + 1; }, 10s)) << text("#message");
  const TaskRow goal = newest_task("console_g1");
  EXPECT_NEAR(goal.gx, 20, 0.3) << text("#message");
  EXPECT_NEAR(goal.gy, 5, 0.3);

  // An initial pose the same way, heading 90 degrees typed in.
  page_->click_element("#pose-theta");
  page_->insert_text("90");
  page_->click_element("#mode-pose");
  click_map(30, 8);
  const std::string pose = "SELECT ROUND(ini_x * 10), ROUND(ini_y * 10), ROUND(ini_theta * 100) FROM robots "
                           "WHERE db_user = 'console_g1' AND removed_at IS NULL";
  ASSERT_TRUE(wait_until([&] { return scalar(pose) != 100; }, 10s)) << text("#message");  // from pose-ini's 10
  auto c = admin();
  auto r = c->query(pose).store();
  ASSERT_EQ(r.size(), 1u);
  EXPECT_NEAR(static_cast<double>(r[0][0]), 300, 3) << text("#message");
  EXPECT_NEAR(static_cast<double>(r[0][1]), 80, 3);
  EXPECT_EQ(static_cast<long long>(r[0][2]), 157);  // pi/2
}

}  // namespace
}  // namespace fleetmap::test
