// fleetmap-loadgen: load generator for the RR/SA path (SPEC 5, 9). Driven by
// scripts/bench-server.sh, which starts a private MariaDB, the robot accounts and the
// servers; this program plays the robots and measures.
//
// Robots speak plain SQL only, as robots written by others do: INSERT INTO rr, then read
// sa_mine in id order and delete what they read. Each robot has its own account and its
// own connection; a few client threads each multiplex many robot connections with the
// non-blocking API of MariaDB Connector/C (the library MySQL++ itself runs on), so that a
// robot waiting on the database never delays another robot's request or poll.
//
// Modes:
//   floor   the bare database path: the same robots and traffic, answered by a minimal
//           loop inside this program (claim rr rows FOR UPDATE SKIP LOCKED, insert a tiny
//           sa row, delete the rr rows, commit, busy-poll; plain C API, two round trips
//           per batch). The figure the server is compared with, measured in the same run.
//   server  the same robots against running fleetmap-server process(es) (--server-pid for
//           their CPU use). Robots send Ready first and keep alive while the others do.
//   lean    a prototype of a batched server inside this program, for the proposals: the
//           server's durable work (trajectories, robots pose and last_seen, gps_fixes, the
//           GetMap window from the spatial index as a seed-text SetMap, OpAck, rr deleted)
//           with robots claimed FOR UPDATE SKIP LOCKED, but in ~4 round trips per batch
//           (multi-row statements; writes and COMMIT as one multi-statement) and the
//           server's idle back-off. Not a server: no validation, no tasks, no Ready.
//   idle    the servers' CPU with no traffic at all for --seconds, then the latency of lone
//           requests (one robot, one request at a time, 100-300 ms apart).
//   report  prints the tables of a results file (JSON lines written by the other modes).
//
// Workloads (--workload): fleet (each robot: SendPos at 3 Hz, Alive every Alive period,
// GetMap 100 m x 100 m around its pose every 5 s, SendGPS every 2 s, phases random),
// quiet (idle robots: Alive only, and the idle polls of the wait policy: what a parked
// fleet costs the database), or lone (one robot, SendGPS, the next 100-300 ms after the
// answer).
//
// What is measured:
//   * answer latency: from the start of the robot's INSERT INTO rr to the end of the
//     SELECT on sa_mine that returned the answer. Robots poll sa_mine on the schedule of
//     RobotClient, the same WaitPolicy object (protocol/wait_policy.h; --wait-* options,
//     defaults the policy's): first_poll_ms after an answered request's INSERT, then gaps of
//     backoff x the time waited within [min_ms, max_ms], and every idle_ms when nothing is
//     due; the figure includes up to one poll gap.
//   * processing lag (SendPos, Alive and the others): a monitor connection (server account)
//     reads the ids present in rr every --monitor-ms; a request whose INSERT had committed
//     before a snapshot and that is absent from it was taken and its deletion committed
//     between the last snapshot that still showed it and this one. The lag is the midpoint
//     of that interval minus the INSERT's start (error <= half the interval). trajectories.t
//     cannot serve: the server stores the request's created_at there, not the time it
//     processed it.
//   * CPU: utime+stime from /proc/<pid>/stat of the server(s) (--server-pid) and of
//     mariadbd (--db-pid) over the measurement window, as % of one core; this process's own
//     CPU (robots, and the floor answerer separately); the whole machine's busy share from
//     /proc/stat (other people's builds show up there).
//   * the database's own counters (SHOW GLOBAL STATUS): statements, commits, fsyncs per s.
#include <mysql.h>  // MariaDB Connector/C: mysql_*_start / mysql_*_cont

#include <poll.h>
#include <sys/resource.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <deque>
#include <fstream>
#include <map>
#include <mutex>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <unordered_map>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "common/geometry/geometry.h"
#include "protocol/connection.h"
#include "protocol/db_settings.h"
#include "protocol/map_codec.h"
#include "protocol/map_store.h"
#include "protocol/params.h"
#include "protocol/sql_util.h"
#include "protocol/wait_policy.h"

namespace {

using Clock = std::chrono::steady_clock;
using TimePoint = Clock::time_point;
using Json = nlohmann::json;

double ms_between(TimePoint a, TimePoint b) { return std::chrono::duration<double, std::milli>(b - a).count(); }
Clock::duration from_ms(double ms) {
  return std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double, std::milli>(ms));
}

// ---------------------------------------------------------------------------------------
// Options and statistics

struct Options {
  std::string mode = "floor";
  std::string workload = "fleet";
  std::string phase = "adhoc", label;
  int robots = 200, first = 1, threads = 8;
  std::string prefix = "lg", password_dir;
  double seconds = 20, warmup = 3, drain = 5;
  fleetmap::WaitPolicy wait;  // RobotClient's, by default its defaults
  double monitor_ms = 2;
  double pos_hz = 3, map_period_s = 5, gps_period_s = 2, alive_period_s = 1;
  double window_m = 100;
  std::string map = "UT_Campus";
  int lone_count = 40;
  int connect_concurrency = 4;
  int floor_threads = 1, floor_batch = 256, lean_threads = 2;
  bool robot_socket = false;
  std::vector<int> server_pids;
  int db_pid = 0;
  int server_procs = 0, workers = 0;
  double poll_max_ms = -1;
  std::string results;
  std::optional<std::string> config;
  unsigned seed = 1;
};

struct Samples {
  std::vector<double> v;
  void add(double x) { v.push_back(x); }
  void merge(const Samples& o) { v.insert(v.end(), o.v.begin(), o.v.end()); }
  Json summary() {
    Json j;
    j["n"] = v.size();
    if (v.empty()) return j;
    std::sort(v.begin(), v.end());
    auto pct = [&](double p) { return v[std::min(v.size() - 1, static_cast<size_t>(p * (v.size() - 1) + 0.5))]; };
    double sum = 0;
    for (double x : v) sum += x;
    j["p50"] = pct(0.5);
    j["p90"] = pct(0.9);
    j["p99"] = pct(0.99);
    j["max"] = v.back();
    j["mean"] = sum / v.size();
    // The fleet goal stores every SendPos within 100 ms: the share of samples within it.
    j["le100"] = static_cast<double>(std::upper_bound(v.begin(), v.end(), 100.0) - v.begin()) / v.size();
    return j;
  }
};

enum Kind : int { kSendPos, kAlive, kGetMap, kSendGps, kReady, kKinds };
const char* const kKindName[kKinds] = {"SendPos", "Alive", "GetMap", "SendGPS", "Ready"};
int expected_answers(Kind k) { return k == kReady ? 2 : (k == kGetMap || k == kSendGps) ? 1 : 0; }

struct KindStats {
  uint64_t sent = 0, answered = 0, errors = 0, unanswered = 0;
  Samples latency, insert, slip, lag;
  void merge(KindStats& o) {
    sent += o.sent;
    answered += o.answered;
    errors += o.errors;
    unanswered += o.unanswered;
    latency.merge(o.latency);
    insert.merge(o.insert);
    slip.merge(o.slip);
    lag.merge(o.lag);
  }
};

struct Stats {
  KindStats kind[kKinds];
  uint64_t polls = 0, deletes = 0, unsolicited = 0, insert_errors = 0, query_errors = 0;
  std::map<std::string, uint64_t> error_codes;
  void merge(Stats& o) {
    for (int k = 0; k < kKinds; ++k) kind[k].merge(o.kind[k]);
    polls += o.polls;
    deletes += o.deletes;
    unsolicited += o.unsolicited;
    insert_errors += o.insert_errors;
    query_errors += o.query_errors;
    for (auto& [c, n] : o.error_codes) error_codes[c] += n;
  }
};

// ---------------------------------------------------------------------------------------
// CPU and database counters

double proc_cpu_s(int pid) {  // utime + stime of a process, seconds
  std::ifstream in("/proc/" + std::to_string(pid) + "/stat");
  std::string s((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto p = s.rfind(')');
  if (p == std::string::npos) return NAN;
  std::istringstream ss(s.substr(p + 2));
  std::string tok;
  double ut = 0, st = 0;
  for (int field = 3; ss >> tok; ++field) {
    if (field == 14) ut = std::stod(tok);
    if (field == 15) {
      st = std::stod(tok);
      break;
    }
  }
  return (ut + st) / sysconf(_SC_CLK_TCK);
}

struct MachineCpu {
  double busy = 0, total = 0;
};
MachineCpu machine_cpu() {
  std::ifstream in("/proc/stat");
  std::string cpu;
  double v[8] = {0};
  in >> cpu;
  for (double& x : v) in >> x;
  MachineCpu m;
  for (double x : v) m.total += x;
  m.busy = m.total - v[3] - v[4];  // minus idle and iowait
  return m;
}

// The machine is shared: the 1-minute load average is recorded beside every figure.
double load_average() {
  std::ifstream in("/proc/loadavg");
  double l = NAN;
  in >> l;
  return l;
}

double self_cpu_s() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_utime.tv_sec + u.ru_stime.tv_sec + (u.ru_utime.tv_usec + u.ru_stime.tv_usec) / 1e6;
}

double thread_cpu_s() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return t.tv_sec + t.tv_nsec / 1e9;
}

const char* const kCounters[] = {"Questions",  "Com_commit", "Handler_commit",     "Com_insert",       "Com_delete",
                                 "Com_select", "Com_update", "Innodb_data_fsyncs", "Innodb_log_writes",
                                 "Innodb_os_log_fsyncs"};

std::map<std::string, double> db_counters(mysqlpp::Connection& c) {
  std::map<std::string, double> out;
  mysqlpp::Query q = c.query("SHOW GLOBAL STATUS");
  for (const mysqlpp::Row& r : q.store()) {
    const std::string k = fleetmap::sql::to_string(r[0]);
    for (const char* want : kCounters)
      if (k == want) out[k] = std::atof(fleetmap::sql::to_string(r[1]).c_str());
  }
  return out;
}

struct Snapshot {
  TimePoint t;
  std::vector<double> servers;
  double db = NAN, self = 0;
  MachineCpu machine;
  double load = NAN;
  std::map<std::string, double> counters;
};

Snapshot snapshot(const Options& o, mysqlpp::Connection* status) {
  Snapshot s;
  s.t = Clock::now();
  for (int pid : o.server_pids) s.servers.push_back(proc_cpu_s(pid));
  if (o.db_pid > 0) s.db = proc_cpu_s(o.db_pid);
  s.self = self_cpu_s();
  s.machine = machine_cpu();
  s.load = load_average();
  if (status) s.counters = db_counters(*status);
  return s;
}

// CPU use between two snapshots, % of one core.
Json cpu_between(const Snapshot& a, const Snapshot& b, double answerer_s) {
  const double wall = ms_between(a.t, b.t) / 1000;
  Json j;
  double servers = 0;
  for (size_t i = 0; i < a.servers.size(); ++i) servers += b.servers[i] - a.servers[i];
  if (!a.servers.empty()) j["server_pct"] = 100 * servers / wall;
  if (!std::isnan(a.db)) j["db_pct"] = 100 * (b.db - a.db) / wall;
  j["robots_pct"] = 100 * (b.self - a.self - answerer_s) / wall;
  if (answerer_s > 0) j["floor_answerer_pct"] = 100 * answerer_s / wall;
  const double cores = std::thread::hardware_concurrency();
  j["machine_pct"] = 100 * cores * (b.machine.busy - a.machine.busy) / std::max(1.0, b.machine.total - a.machine.total);
  j["cores"] = cores;
  j["load_start"] = a.load;
  j["load_end"] = b.load;
  Json c;
  for (auto& [k, v] : b.counters)
    if (a.counters.count(k)) c[k] = (v - a.counters.at(k)) / wall;
  j["db_per_s"] = c;
  return j;
}

// ---------------------------------------------------------------------------------------
// Shared state between the main thread, the robot threads, the monitor and the answerer

struct Tracked {
  uint64_t id;
  Kind kind;
  TimePoint t0, committed;
};

struct Bounds {
  double xmin = 0, ymin = 0, xmax = 100, ymax = 100;
};

struct Shared {
  explicit Shared(const Options& o) : opt(o) {}
  const Options& opt;
  Bounds bounds;
  std::string host, database, socket;
  unsigned port = 0;
  std::atomic<int> setup_done{0}, failed{0}, threads_done{0};
  std::atomic<bool> go{false}, stop_helpers{false};
  TimePoint t_go, m_start, m_end, drain_end;  // published by `go`
  std::mutex mu;
  std::vector<Tracked> inbox;  // for the monitor
  std::mutex err_mu;
  int error_lines = 0;
  void report_error(const std::string& what) {
    std::lock_guard l(err_mu);
    if (++error_lines <= 10) std::fprintf(stderr, "loadgen: %s\n", what.c_str());
    if (error_lines == 10) std::fprintf(stderr, "loadgen: (further errors not shown)\n");
  }
};

// ---------------------------------------------------------------------------------------
// One robot: its connection and its state machine

struct Pending {
  Kind kind;
  TimePoint sched;
};
struct Outstanding {
  Kind kind;
  TimePoint t0;
  int left;
  bool in_window;
};

struct Robot {
  std::string name, password;
  MYSQL* db = nullptr;
  enum Stage { kIdle, kConnect, kClean, kInsert, kSelect, kStore, kDelete, kDead } stage = kIdle;
  int wait = 0;
  TimePoint deadline{};
  bool connected = false, cleaned = false, setup_counted = false, registered = false;
  std::optional<unsigned> robot_id;
  double alive_s = 1;
  std::string sql;
  Pending cur{};
  TimePoint t0{};
  MYSQL_RES* res = nullptr;
  std::deque<Pending> queue;
  TimePoint next[4]{};
  bool scheduled = false;
  std::map<uint64_t, Outstanding> awaiting;
  uint64_t last_answer = 0;
  TimePoint next_poll{}, next_idle_poll{};
  double x = 0, y = 0, theta = 0, v = 1.0;
  int lone_left = 0;
  TimePoint lone_next{}, setup_alive{};
  std::mt19937 rng;
};

class RobotThread {
 public:
  RobotThread(Shared& sh, std::vector<Robot*> robots) : sh_(sh), o_(sh.opt), robots_(std::move(robots)) {}
  void run();
  Stats stats;

 private:
  void act(Robot& r, TimePoint now);
  void start_connects();
  void resume(Robot& r, int flags);
  void finished(Robot& r);  // the async operation in hand completed
  void start_query(Robot& r, Robot::Stage stage);
  void after_insert(Robot& r, TimePoint now);
  void after_store(Robot& r, TimePoint now);
  void fail(Robot& r, const std::string& what);
  std::string params_for(Robot& r, Kind k);
  void schedule(Robot& r, TimePoint now);
  bool in_window(TimePoint t) const { return sh_.go && t >= sh_.m_start && t < sh_.m_end; }
  bool done(const Robot& r, TimePoint now) const;
  bool needs_ready() const { return o_.mode == "server" || o_.mode == "idle"; }  // the server wants Ready first

  Shared& sh_;
  const Options& o_;
  std::vector<Robot*> robots_;
  std::vector<Tracked> tracked_;
  bool go_seen_ = false;
  size_t next_connect_ = 0;
  int connecting_ = 0;
};

int poll_events(int wait) {
  int e = 0;
  if (wait & MYSQL_WAIT_READ) e |= POLLIN;
  if (wait & MYSQL_WAIT_WRITE) e |= POLLOUT;
  if (wait & MYSQL_WAIT_EXCEPT) e |= POLLPRI;
  return e;
}

void RobotThread::fail(Robot& r, const std::string& what) {
  sh_.report_error(r.name + ": " + what);
  r.stage = Robot::kDead;
  r.wait = 0;
  if (!r.setup_counted) {
    r.setup_counted = true;
    sh_.failed++;
  }
}

void RobotThread::start_query(Robot& r, Robot::Stage stage) {
  int err = 0;
  r.stage = stage;
  r.wait = mysql_real_query_start(&err, r.db, r.sql.data(), r.sql.size());
  if (r.wait & MYSQL_WAIT_TIMEOUT)
    r.deadline = Clock::now() + std::chrono::milliseconds(mysql_get_timeout_value_ms(r.db));
  if (r.wait == 0) finished(r);
}

void RobotThread::resume(Robot& r, int flags) {
  switch (r.stage) {
    case Robot::kConnect: {
      MYSQL* ret = nullptr;
      r.wait = mysql_real_connect_cont(&ret, r.db, flags);
      break;
    }
    case Robot::kClean:
    case Robot::kInsert:
    case Robot::kSelect:
    case Robot::kDelete: {
      int err = 0;
      r.wait = mysql_real_query_cont(&err, r.db, flags);
      break;
    }
    case Robot::kStore:
      r.wait = mysql_store_result_cont(&r.res, r.db, flags);
      break;
    default:
      return;
  }
  if (r.wait & MYSQL_WAIT_TIMEOUT)
    r.deadline = Clock::now() + std::chrono::milliseconds(mysql_get_timeout_value_ms(r.db));
  if (r.wait == 0) finished(r);
}

void RobotThread::finished(Robot& r) {
  const TimePoint now = Clock::now();
  const Robot::Stage stage = r.stage;
  r.stage = Robot::kIdle;
  if (stage == Robot::kConnect) --connecting_;
  if (mysql_errno(r.db) != 0 && stage != Robot::kStore) {
    const unsigned e = mysql_errno(r.db);
    const std::string msg = std::string(mysql_error(r.db)) + " (error " + std::to_string(e) + ")";
    if (stage == Robot::kInsert)
      stats.insert_errors++;
    else
      stats.query_errors++;
    if (stage == Robot::kConnect || (e >= 2000 && e < 3000)) return fail(r, msg);
    sh_.report_error(r.name + ": " + msg);
    if (stage == Robot::kInsert && r.cur.kind == kReady) return fail(r, "Ready not sent");
    return act(r, now);
  }
  switch (stage) {
    case Robot::kConnect:
      r.connected = true;
      r.sql = "DELETE FROM sa_mine";  // answers left by an earlier run
      return start_query(r, Robot::kClean);
    case Robot::kClean:
      r.cleaned = true;
      if (needs_ready()) {
        r.queue.push_back({kReady, now});
      }
      break;
    case Robot::kInsert:
      after_insert(r, now);
      break;
    case Robot::kSelect:
      r.wait = mysql_store_result_start(&r.res, r.db);
      r.stage = Robot::kStore;
      if (r.wait == 0) return finished(r);
      return;
    case Robot::kStore:
      if (!r.res) {
        stats.query_errors++;
        sh_.report_error(r.name + ": reading sa_mine: " + mysql_error(r.db));
        if (mysql_errno(r.db) >= 2000 && mysql_errno(r.db) < 3000) return fail(r, "connection lost");
        break;
      }
      after_store(r, now);
      if (r.stage != Robot::kIdle) return;  // a DELETE started
      break;
    case Robot::kDelete:
      stats.deletes++;
      break;
    default:
      break;
  }
  if (!r.setup_counted && r.cleaned && (!needs_ready() || r.registered)) {
    r.setup_counted = true;
    sh_.setup_done++;
  }
  act(r, now);
}

std::string RobotThread::params_for(Robot& r, Kind k) {
  char b[256];
  switch (k) {
    case kSendPos: {
      // Move on at v for a third of a second; turn back at the margins of the map.
      const double dt = 1.0 / o_.pos_hz;
      const Bounds& m = sh_.bounds;
      r.x += r.v * std::cos(r.theta) * dt;
      r.y += r.v * std::sin(r.theta) * dt;
      if (r.x < m.xmin + 60 || r.x > m.xmax - 60 || r.y < m.ymin + 60 || r.y > m.ymax - 60)
        r.theta = std::atan2((m.ymin + m.ymax) / 2 - r.y, (m.xmin + m.xmax) / 2 - r.x);
      std::snprintf(b, sizeof b, R"({"x":%.3f,"y":%.3f,"theta":%.4f,"v":%.2f,"w":0.0})", r.x, r.y, r.theta, r.v);
      return b;
    }
    case kGetMap:
      std::snprintf(b, sizeof b, R"({"x":%.3f,"y":%.3f,"w":%g,"h":%g})", r.x, r.y, o_.window_m, o_.window_m);
      return b;
    case kSendGps: {
      const double lat0 = 30.2861, lon0 = -97.7394;  // UT Austin
      std::snprintf(b, sizeof b, R"({"lat":%.8f,"lon":%.8f})", lat0 + r.y / 111111.0,
                    lon0 + r.x / (111111.0 * std::cos(lat0 * M_PI / 180)));
      return b;
    }
    case kReady:
      std::snprintf(b, sizeof b, R"({"magic":%u,"encoding":"seed+compress"})", static_cast<unsigned>(r.rng() >> 1));
      return b;
    default:
      return "{}";
  }
}

void RobotThread::after_insert(Robot& r, TimePoint now) {
  const uint64_t id = mysql_insert_id(r.db);
  const Kind k = r.cur.kind;
  const bool win = in_window(r.t0);
  if (win) {
    KindStats& s = stats.kind[k];
    s.sent++;
    s.insert.add(ms_between(r.t0, now));
    s.slip.add(ms_between(r.cur.sched, r.t0));
    if (o_.mode != "idle" && o_.monitor_ms > 0) tracked_.push_back({id, k, r.t0, now});
  }
  if (expected_answers(k) > 0) {
    r.awaiting[id] = {k, r.t0, expected_answers(k), win};
    r.next_poll = now + from_ms(o_.wait.first_poll_ms);  // as RobotClient does
  }
}

void RobotThread::after_store(Robot& r, TimePoint now) {
  stats.polls++;
  std::string del;
  MYSQL_ROW row;
  while ((row = mysql_fetch_row(r.res))) {
    const uint64_t id = std::strtoull(row[0], nullptr, 10);
    r.last_answer = std::max(r.last_answer, id);
    del += (del.empty() ? "" : ",") + std::string(row[0]);
    if (!row[1]) {
      stats.unsolicited++;
      continue;
    }
    const uint64_t req = std::strtoull(row[1], nullptr, 10);
    auto it = r.awaiting.find(req);
    if (it == r.awaiting.end()) {
      stats.unsolicited++;
      continue;
    }
    Outstanding& w = it->second;
    const std::string op = row[2] ? row[2] : "";
    if (op == "Error") {
      stats.kind[w.kind].errors++;
      const Json p = Json::parse(row[3] ? row[3] : "{}", nullptr, false);
      const std::string code = p.is_object() ? p.value("code", std::string("?")) : "?";
      stats.error_codes[std::string(kKindName[w.kind]) + ":" + code]++;
      w.left = 0;
      if (w.kind == kReady) {
        r.awaiting.erase(it);
        mysql_free_result(r.res);
        r.res = nullptr;
        return fail(r, "Ready refused: " + code);
      }
    } else if (op == "Start") {
      const Json p = Json::parse(row[3] ? row[3] : "{}", nullptr, false);
      if (p.is_object()) {
        r.robot_id = p.value("robot_id", 0u);
        r.alive_s = p.value("alive_period_s", o_.alive_period_s);
      }
      w.left--;
    } else {
      w.left--;
    }
    if (w.left <= 0) {
      if (w.kind == kReady) {
        r.registered = true;
        r.setup_alive = now + from_ms(1000 * r.alive_s);
      }
      if (w.in_window) {
        stats.kind[w.kind].answered++;
        stats.kind[w.kind].latency.add(ms_between(w.t0, now));
      }
      r.awaiting.erase(it);
    }
  }
  mysql_free_result(r.res);
  r.res = nullptr;
  // The next poll by the wait policy, from the oldest answer due (as RobotClient).
  double waited_ms = 0;
  for (const auto& [id, w] : r.awaiting) waited_ms = std::max(waited_ms, ms_between(w.t0, now));
  r.next_poll = now + from_ms(o_.wait.answer_gap_ms(waited_ms));
  r.next_idle_poll = now + from_ms(o_.wait.idle_ms);
  if (!del.empty()) {
    r.sql = "DELETE FROM sa_mine WHERE id IN (" + del + ")";
    start_query(r, Robot::kDelete);
  }
}

void RobotThread::schedule(Robot& r, TimePoint now) {
  if (!r.scheduled) {
    r.scheduled = true;
    std::uniform_real_distribution<double> u(0, 1);
    const double periods[4] = {1.0 / o_.pos_hz, r.alive_s, o_.map_period_s, o_.gps_period_s};
    for (int k = 0; k < 4; ++k) r.next[k] = sh_.t_go + from_ms(1000 * periods[k] * u(r.rng));
    r.lone_left = o_.lone_count;
    r.lone_next = sh_.t_go;
    r.next_idle_poll = sh_.t_go + from_ms(o_.wait.idle_ms * u(r.rng));
  }
  if (now >= sh_.m_end) return;
  if (o_.workload == "lone") {
    if (r.lone_left > 0 && r.awaiting.empty() && r.queue.empty() && now >= r.lone_next) {
      r.queue.push_back({kSendGps, now});
      r.lone_left--;
      std::uniform_real_distribution<double> gap(100, 300);
      r.lone_next = now + from_ms(gap(r.rng));  // counted from the send; the answer comes first
    }
    return;
  }
  const double periods[4] = {1.0 / o_.pos_hz, r.alive_s, o_.map_period_s, o_.gps_period_s};
  for (int k = 0; k < 4; ++k)
    while ((o_.workload != "quiet" || k == kAlive) && r.next[k] <= now && r.next[k] < sh_.m_end) {
      r.queue.push_back({static_cast<Kind>(k), r.next[k]});
      r.next[k] += from_ms(1000 * periods[k]);
    }
}

bool RobotThread::done(const Robot& r, TimePoint now) const {
  if (r.stage == Robot::kDead) return true;
  if (!sh_.go || r.stage != Robot::kIdle) return false;
  if (o_.workload == "lone") return r.scheduled && r.lone_left == 0 && r.queue.empty() && r.awaiting.empty();
  if (now < sh_.m_end) return false;
  return (r.queue.empty() && r.awaiting.empty()) || now >= sh_.drain_end;
}

void RobotThread::act(Robot& r, TimePoint now) {
  if (r.stage != Robot::kIdle || !r.cleaned) return;
  if (sh_.go && (!needs_ready() || r.registered)) {
    schedule(r, now);
  } else if (r.registered && now >= r.setup_alive) {
    // Registered while others still connect: keep alive, or the server marks it lost.
    r.queue.push_back({kAlive, now});
    r.setup_alive = now + from_ms(1000 * r.alive_s);
  }
  if (!r.queue.empty()) {
    r.cur = r.queue.front();
    r.queue.pop_front();
    const std::string rid = r.robot_id ? std::to_string(*r.robot_id) : "NULL";
    r.sql = "INSERT INTO rr (robot_id, op, params) VALUES (" + rid + ", '" + kKindName[r.cur.kind] + "', '" +
            params_for(r, r.cur.kind) + "')";
    r.t0 = Clock::now();
    if (sh_.go && r.t0 >= sh_.m_end && r.cur.kind != kReady) {  // the window closed while it waited
      r.queue.clear();
      return;
    }
    return start_query(r, Robot::kInsert);
  }
  const bool poll_answer = !r.awaiting.empty() && now >= r.next_poll;
  const bool poll_idle =
      sh_.go && o_.wait.idle_ms > 0 && now >= r.next_idle_poll && now < sh_.m_end && o_.workload != "lone";
  if (poll_answer || poll_idle) {
    r.sql = "SELECT id, request_id, op, params, payload FROM sa_mine WHERE id > " + std::to_string(r.last_answer) +
            " ORDER BY id LIMIT 100";
    return start_query(r, Robot::kSelect);
  }
}

void RobotThread::start_connects() {
  // A few connects at a time: a storm of them overflows mariadbd's listen backlog
  // (back_log), and the connections left in the kernel's queue time out.
  while (connecting_ < o_.connect_concurrency && next_connect_ < robots_.size()) {
    Robot* r = robots_[next_connect_++];
    ++connecting_;
    r->db = mysql_init(nullptr);
    mysql_options(r->db, MYSQL_OPT_NONBLOCK, 0);
    mysql_options(r->db, MYSQL_SET_CHARSET_NAME, "utf8mb4");
    unsigned timeout = 30;
    mysql_options(r->db, MYSQL_OPT_CONNECT_TIMEOUT, &timeout);
    MYSQL* ret = nullptr;
    r->stage = Robot::kConnect;
    const bool sock = o_.robot_socket && !sh_.socket.empty();
    r->wait = mysql_real_connect_start(&ret, r->db, sock ? "localhost" : sh_.host.c_str(), r->name.c_str(),
                                       r->password.c_str(), sh_.database.c_str(), sock ? 0 : sh_.port,
                                       sock ? sh_.socket.c_str() : nullptr, 0);
    if (r->wait & MYSQL_WAIT_TIMEOUT)
      r->deadline = Clock::now() + std::chrono::milliseconds(mysql_get_timeout_value_ms(r->db));
    if (r->wait == 0) finished(*r);
  }
}

void RobotThread::run() {
  std::vector<pollfd> fds;
  std::vector<Robot*> who;
  for (;;) {
    start_connects();
    TimePoint now = Clock::now();
    if (!go_seen_ && sh_.go.load(std::memory_order_acquire)) go_seen_ = true;
    bool all_done = true;
    TimePoint wake = now + std::chrono::milliseconds(20);
    fds.clear();
    who.clear();
    for (Robot* r : robots_) {
      if (r->stage == Robot::kIdle) act(*r, now);
      if (!done(*r, now)) all_done = false;
      if (r->stage == Robot::kIdle) {
        // When does this robot next have something to do?
        if (!r->queue.empty()) wake = now;
        if (!r->awaiting.empty()) wake = std::min(wake, r->next_poll);
        if (!go_seen_ && r->registered) wake = std::min(wake, r->setup_alive);
        if (go_seen_) {
          if (o_.workload != "lone") {
            for (int k = 0; k < 4; ++k)
              if (o_.workload != "quiet" || k == kAlive) wake = std::min(wake, r->next[k]);
            if (o_.wait.idle_ms > 0) wake = std::min(wake, r->next_idle_poll);
          } else if (r->lone_left > 0) {
            wake = std::min(wake, r->lone_next);
          }
        }
      } else if (r->stage != Robot::kDead && r->wait) {
        fds.push_back({mysql_get_socket(r->db), static_cast<short>(poll_events(r->wait)), 0});
        who.push_back(r);
        if (r->wait & MYSQL_WAIT_TIMEOUT) wake = std::min(wake, r->deadline);
      }
    }
    if (!tracked_.empty()) {
      std::lock_guard l(sh_.mu);
      sh_.inbox.insert(sh_.inbox.end(), tracked_.begin(), tracked_.end());
      tracked_.clear();
    }
    if (all_done && go_seen_) break;
    const double wait_ms = std::max(0.0, ms_between(now, wake));
    // poll() takes whole milliseconds; sub-millisecond waits use ppoll.
    timespec ts{static_cast<time_t>(wait_ms / 1000), static_cast<long>(std::fmod(wait_ms, 1000.0) * 1e6)};
    const int n = ppoll(fds.data(), fds.size(), &ts, nullptr);
    if (n < 0 && errno != EINTR) {
      std::perror("loadgen: ppoll");
      break;
    }
    now = Clock::now();
    for (size_t i = 0; i < fds.size(); ++i) {
      Robot& r = *who[i];
      int flags = 0;
      const short ev = fds[i].revents;
      if (ev & POLLIN) flags |= MYSQL_WAIT_READ;
      if (ev & POLLOUT) flags |= MYSQL_WAIT_WRITE;
      if (ev & POLLPRI) flags |= MYSQL_WAIT_EXCEPT;
      if (ev & (POLLERR | POLLHUP)) flags |= MYSQL_WAIT_READ | MYSQL_WAIT_WRITE;
      if (!flags && (r.wait & MYSQL_WAIT_TIMEOUT) && now >= r.deadline) flags = MYSQL_WAIT_TIMEOUT;
      if (flags) resume(r, flags);
    }
  }
  for (Robot* r : robots_) {
    for (auto& [id, w] : r->awaiting)
      if (w.in_window) stats.kind[w.kind].unanswered++;
    if (r->db) mysql_close(r->db);
    r->db = nullptr;
  }
  sh_.threads_done++;
}

// ---------------------------------------------------------------------------------------
// The monitor: when does a request leave rr?

void monitor(Shared& sh, const fleetmap::DbSettings& db, Stats& stats, Samples& backlog, uint64_t& queries,
             size_t robot_threads) {
  auto conn = fleetmap::connect(db);
  struct Entry {
    Kind kind;
    TimePoint t0, committed, seen;  // seen: start of the last snapshot that still showed it
  };
  std::map<uint64_t, Entry> pending;
  std::vector<Tracked> incoming;
  while (sh.threads_done.load() < static_cast<int>(robot_threads) || !pending.empty()) {
    {
      std::lock_guard l(sh.mu);
      incoming.swap(sh.inbox);
    }
    for (const Tracked& t : incoming) pending[t.id] = {t.kind, t.t0, t.committed, t.committed};
    incoming.clear();
    const TimePoint q0 = Clock::now();
    if (pending.empty()) {
      if (sh.threads_done.load() >= static_cast<int>(robot_threads)) break;
      std::this_thread::sleep_for(from_ms(sh.opt.monitor_ms));
      continue;
    }
    std::vector<uint64_t> present;
    mysqlpp::Query q = conn->query();
    q << "SELECT id FROM rr WHERE id >= " << pending.begin()->first << " ORDER BY id LIMIT 1000000";
    for (const mysqlpp::Row& r : q.store()) present.push_back(fleetmap::sql::to_uint(r[0]));
    ++queries;
    if (q0 >= sh.m_start && q0 < sh.m_end) backlog.add(static_cast<double>(present.size()));
    for (auto it = pending.begin(); it != pending.end();) {
      if (std::binary_search(present.begin(), present.end(), it->first)) {
        it->second.seen = q0;
        ++it;
        continue;
      }
      // Gone between the last snapshot that showed it (or its commit) and this one.
      const TimePoint gone = it->second.seen + (q0 - it->second.seen) / 2;
      stats.kind[it->second.kind].lag.add(ms_between(it->second.t0, gone));
      it = pending.erase(it);
    }
    // Give up on requests the server never took (stopped, or far behind).
    if (sh.threads_done.load() >= static_cast<int>(robot_threads) && Clock::now() > sh.drain_end) {
      for (auto& [id, e] : pending) stats.kind[e.kind].unanswered++;  // not taken out of rr in time
      pending.clear();
      break;
    }
    const TimePoint next = q0 + from_ms(sh.opt.monitor_ms);
    if (Clock::now() < next) std::this_thread::sleep_until(next);
  }
}

// ---------------------------------------------------------------------------------------
// The floor: a minimal answering loop without server logic

void floor_answerer(Shared& sh, const fleetmap::DbSettings& db, double& cpu_in_window, uint64_t& handled,
                    uint64_t& empty_polls) {
  // The leanest path MariaDB offers: plain C API, two round trips per batch. The claim
  // (the transaction begins with it: autocommit off) doubles as the busy poll; the
  // answers, the delete and the commit go together as one multi-statement.
  MYSQL* c = mysql_init(nullptr);
  mysql_options(c, MYSQL_SET_CHARSET_NAME, "utf8mb4");
  const bool sock = !db.socket.empty();
  if (!mysql_real_connect(c, sock ? "localhost" : db.host.c_str(), db.user.c_str(), db.password.c_str(),
                          db.database.c_str(), sock ? 0 : db.port, sock ? db.socket.c_str() : nullptr,
                          CLIENT_MULTI_STATEMENTS)) {
    sh.report_error(std::string("floor answerer: ") + mysql_error(c));
    mysql_close(c);
    return;
  }
  struct Retry {};  // deadlock or lock wait timeout: roll back and claim again
  auto fail = [&]() {
    const unsigned e = mysql_errno(c);
    if (e == 1213 || e == 1205) {
      mysql_query(c, "ROLLBACK");
      throw Retry{};
    }
    throw std::runtime_error("floor answerer: " + std::string(mysql_error(c)));
  };
  auto run = [&](const std::string& q) {
    if (mysql_real_query(c, q.data(), q.size()) != 0) fail();
    do {  // drain every result of a multi-statement
      if (MYSQL_RES* r = mysql_store_result(c)) mysql_free_result(r);
    } while (mysql_next_result(c) == 0);
  };
  std::unordered_map<std::string, unsigned> ids;
  mysql_query(c, "SELECT db_user, id FROM robots");
  if (MYSQL_RES* r = mysql_store_result(c)) {
    while (MYSQL_ROW row = mysql_fetch_row(r)) ids[row[0]] = static_cast<unsigned>(std::strtoul(row[1], nullptr, 10));
    mysql_free_result(r);
  }
  run("SET SESSION TRANSACTION ISOLATION LEVEL READ COMMITTED");
  run("SET autocommit = 0");
  uint64_t retries = 0;
  const std::string claim = "SELECT id, db_user, op FROM rr ORDER BY id LIMIT " + std::to_string(sh.opt.floor_batch) +
                            " FOR UPDATE SKIP LOCKED";
  double cpu0 = NAN, cpu1 = NAN;
  try {
    while (!sh.stop_helpers.load()) {
      if (sh.go) {
        const TimePoint now = Clock::now();
        if (std::isnan(cpu0) && now >= sh.m_start) cpu0 = thread_cpu_s();
        if (std::isnan(cpu1) && now >= sh.m_end) cpu1 = thread_cpu_s();
      }
      try {
        if (mysql_real_query(c, claim.data(), claim.size()) != 0) fail();
        MYSQL_RES* res = mysql_store_result(c);
        std::string del, ins;
        size_t n = 0;
        while (MYSQL_ROW row = res ? mysql_fetch_row(res) : nullptr) {
          ++n;
          const std::string id = row[0], user = row[1], op = row[2];
          del += (del.empty() ? "" : ",") + id;
          if (op == "GetMap" || op == "SendGPS" || op == "Ready") {
            const auto it = ids.find(user);
            const std::string rid = std::to_string(it == ids.end() ? 0 : it->second);
            ins += std::string(ins.empty() ? "" : ",") + "(" + rid + ", '" + user + "', " + id +
                   ", 'OpAck', '{\"request_id\":" + id + "}', SYSDATE(6))";
            if (op == "Ready") ins += ",(" + rid + ", '" + user + "', " + id + ", 'SetMap', '{}', SYSDATE(6))";
          }
        }
        if (res) mysql_free_result(res);
        if (n == 0) {  // nothing locked: the open transaction holds nothing; poll again at once
          ++empty_polls;
          continue;
        }
        std::string q;
        if (!ins.empty())
          q = "INSERT INTO sa (robot_id, db_user, request_id, op, params, created_at) VALUES " + ins + "; ";
        q += "DELETE FROM rr WHERE id IN (" + del + "); COMMIT";
        run(q);
        handled += n;
      } catch (const Retry&) {
        ++retries;
      }
    }
  } catch (const std::exception& e) {
    sh.report_error(e.what());
  }
  if (retries) sh.report_error("floor answerer: " + std::to_string(retries) + " batch(es) retried after a deadlock");
  mysql_close(c);
  if (std::isnan(cpu1)) cpu1 = thread_cpu_s();
  cpu_in_window = std::isnan(cpu0) ? 0 : cpu1 - cpu0;
}

// ---------------------------------------------------------------------------------------
// Lean: a prototype of a batched server, for the proposals. The same durable work as
// fleetmap-server (trajectory row and robots pose per SendPos, gps_fixes row and OpAck per
// SendGPS, the clipped window from the spatial index as a seed-text SetMap per GetMap,
// last_seen, rr deleted, all in one transaction per batch, robots claimed FOR UPDATE SKIP
// LOCKED before their requests are read), but batched: multi-row statements, and the
// writes and the COMMIT sent as one multi-statement. No per-request savepoint, no task or
// map-info look-ups (a real server would cache them), no validation beyond JSON parsing.
// Idle back-off as fleetmap-server's: 0.25 ms doubling up to --poll-max-ms.

void lean_answerer(Shared& sh, const fleetmap::DbSettings& db, double& cpu_in_window, uint64_t& handled,
                   uint64_t& empty_polls) {
  using namespace fleetmap;
  mysqlpp::Connection conn(true);
  conn.set_option(new mysqlpp::SetCharsetNameOption("utf8mb4"));
  conn.set_option(new mysqlpp::MultiStatementsOption(true));
  const bool sock = !db.socket.empty();
  conn.connect(db.database.c_str(), sock ? db.socket.c_str() : db.host.c_str(), db.user.c_str(), db.password.c_str(),
               sock ? 0 : db.port);
  execute(conn, "SET SESSION TRANSACTION ISOLATION LEVEL READ COMMITTED");
  execute(conn, "SET SESSION innodb_lock_wait_timeout = 1");
  execute(conn, "SET autocommit = 0");  // the first read opens the transaction; the multi-statement ends it
  MapStore maps(conn);
  const Rect border{sh.bounds.xmin, sh.bounds.ymin, sh.bounds.xmax, sh.bounds.ymax};
  const size_t batch = static_cast<size_t>(sh.opt.floor_batch);
  const double poll_max = sh.opt.poll_max_ms >= 0 ? sh.opt.poll_max_ms : 10;
  double idle_ms = 0, cpu0 = NAN, cpu1 = NAN;
  auto num_or = [](const Json& j, const char* k) {
    return j.contains(k) && j[k].is_number() ? j[k].get<double>() : 0.0;
  };
  while (!sh.stop_helpers.load()) {
    if (sh.go) {
      const TimePoint now = Clock::now();
      if (std::isnan(cpu0) && now >= sh.m_start) cpu0 = thread_cpu_s();
      if (std::isnan(cpu1) && now >= sh.m_end) cpu1 = thread_cpu_s();
    }
    try {
      // 1. Who waits, oldest first: a bounded read of rr's head (O(batch), no locks).
      std::vector<std::string> accounts;
      {
        mysqlpp::Query q = conn.query();
        q << "SELECT db_user FROM rr ORDER BY id LIMIT " << batch;
        std::set<std::string> seen;
        for (const mysqlpp::Row& r : q.store())
          if (seen.insert(sql::to_string(r[0])).second) accounts.push_back(sql::to_string(r[0]));
      }
      if (accounts.empty()) {
        ++empty_polls;
        idle_ms = std::clamp(idle_ms * 2, 0.25, poll_max);
        std::this_thread::sleep_for(from_ms(idle_ms));
        continue;
      }
      idle_ms = 0;
      // 2. Claim the robots, 3. read their requests in id order.
      struct Bot {
        unsigned id;
        std::optional<unsigned> map_id;
        std::string user;
        std::string last_seen;
        std::optional<std::array<double, 4>> pose;
      };
      std::map<std::string, Bot> bots;
      {
        mysqlpp::Query q = conn.query();
        q << "SELECT id, map_id, db_user FROM robots WHERE db_user IN (";
        for (size_t i = 0; i < accounts.size(); ++i) q << (i ? "," : "") << mysqlpp::quote << accounts[i];
        q << ") FOR UPDATE SKIP LOCKED";
        for (const mysqlpp::Row& r : q.store()) {
          Bot b{static_cast<unsigned>(sql::to_uint(r[0])), std::nullopt, sql::to_string(r[2]), "", std::nullopt};
          if (!r[1].is_null()) b.map_id = static_cast<unsigned>(sql::to_uint(r[1]));
          bots.emplace(b.user, b);
        }
      }
      if (bots.empty()) continue;  // another worker holds them; nothing is locked
      mysqlpp::Query rq = conn.query();
      rq << "SELECT id, db_user, op, params, created_at FROM rr WHERE db_user IN (";
      {
        size_t i = 0;
        for (auto& [u, b] : bots) rq << (i++ ? "," : "") << mysqlpp::quote << u;
      }
      rq << ") ORDER BY id LIMIT " << batch;
      const mysqlpp::StoreQueryResult reqs = rq.store();
      // 4. Work, then one multi-statement with every write and the COMMIT.
      std::string traj, gps, del;
      mysqlpp::Query w = conn.query();
      bool any_answer = false;
      std::ostringstream answers;
      for (const mysqlpp::Row& r : reqs) {
        const std::string id = sql::to_string(r[0]), user = sql::to_string(r[1]), op = sql::to_string(r[2]),
                          at = sql::to_string(r[4]);
        Bot& b = bots.at(user);
        b.last_seen = at;
        del += (del.empty() ? "" : ",") + id;
        const Json p = Json::parse(sql::to_string(r[3]), nullptr, false);
        if (!p.is_object()) continue;
        char buf[320];
        if (op == "SendPos") {
          const double x = num_or(p, "x"), y = num_or(p, "y"), th = num_or(p, "theta"), v = num_or(p, "v");
          std::snprintf(buf, sizeof buf, "%s(%u,'%s',%.17g,%.17g,%.17g,%.17g,%.17g,Point(%.17g,%.17g))",
                        traj.empty() ? "" : ",", b.id, at.c_str(), x, y, th, v, num_or(p, "w"), x, y);
          traj += buf;
          b.pose = std::array<double, 4>{x, y, th, v};
        } else if (op == "SendGPS") {
          std::snprintf(buf, sizeof buf, "%s(%u,'%s',%.17g,%.17g)", gps.empty() ? "" : ",", b.id, at.c_str(),
                        num_or(p, "lat"), num_or(p, "lon"));
          gps += buf;
          w << (any_answer ? "," : "") << "(" << b.id << "," << mysqlpp::quote << user << "," << id
            << ",'OpAck','{\"request_id\":" << id << "}',NULL,SYSDATE(6))";
          any_answer = true;
        } else if (op == "GetMap" && b.map_id) {
          const Rect win =
              intersection(Rect::centred({num_or(p, "x"), num_or(p, "y")}, std::min(num_or(p, "w"), 1000.0),
                                         std::min(num_or(p, "h"), 1000.0)),
                           border);
          const Map m = maps.window(*b.map_id, win);
          w << (any_answer ? "," : "") << "(" << b.id << "," << mysqlpp::quote << user << "," << id << ",'SetMap',"
            << mysqlpp::quote << encode(set_map_params(m, MapEncoding::Seed)).dump() << "," << mysqlpp::quote
            << encode_map(m, MapEncoding::Seed) << ",SYSDATE(6))";
          any_answer = true;
        }
      }
      const std::string sa_values = w.str();
      mysqlpp::Query m = conn.query();
      if (!traj.empty()) m << "INSERT INTO trajectories (robot_id, t, x, y, theta, v, w, pos) VALUES " << traj << ";";
      if (!gps.empty()) m << "INSERT INTO gps_fixes (robot_id, t, lat, lon) VALUES " << gps << ";";
      if (any_answer)
        m << "INSERT INTO sa (robot_id, db_user, request_id, op, params, payload, created_at) VALUES " << sa_values
          << ";";
      for (auto& [u, b] : bots) {
        if (b.last_seen.empty()) continue;
        m << "UPDATE robots SET last_seen = GREATEST(COALESCE(last_seen, 0), '" << b.last_seen << "')";
        if (b.pose) {
          char buf[200];
          std::snprintf(buf, sizeof buf, ", x = %.17g, y = %.17g, theta = %.17g, v = %.17g", (*b.pose)[0], (*b.pose)[1],
                        (*b.pose)[2], (*b.pose)[3]);
          m << buf;
        }
        m << " WHERE id = " << b.id << ";";
      }
      if (!del.empty()) m << "DELETE FROM rr WHERE id IN (" << del << ");";
      m << "COMMIT";
      m.store();
      while (m.more_results()) m.store_next();
      handled += reqs.size();
    } catch (const mysqlpp::Exception& e) {
      sh.report_error(std::string("lean answerer: ") + e.what());
      try {
        execute(conn, "ROLLBACK");
      } catch (const mysqlpp::Exception&) {
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
  }
  if (std::isnan(cpu1)) cpu1 = thread_cpu_s();
  cpu_in_window = std::isnan(cpu0) ? 0 : cpu1 - cpu0;
}

// ---------------------------------------------------------------------------------------
// Report: tables of a results file

std::string fmt(const Json& j, const char* key, const char* f = "%.2f") {
  if (!j.is_object() || !j.contains(key) || !j[key].is_number()) return "-";
  char b[32];
  std::snprintf(b, sizeof b, f, j[key].get<double>());
  return b;
}
double num(const Json& j, std::initializer_list<const char*> path) {
  const Json* p = &j;
  for (const char* k : path) {
    if (!p->is_object() || !p->contains(k)) return NAN;
    p = &(*p)[k];
  }
  return p->is_number() ? p->get<double>() : NAN;
}
std::string f2(double v, const char* f = "%.2f") {
  if (std::isnan(v)) return "-";
  char b[32];
  std::snprintf(b, sizeof b, f, v);
  return b;
}
// Latencies: two decimals below 100 ms, fewer above (a collapsed run shows seconds).
std::string ms(double v) { return f2(v, v >= 1000 ? "%.0f" : v >= 100 ? "%.1f" : "%.2f"); }
std::string ratio(double a, double b) { return (std::isnan(a) || std::isnan(b) || b <= 0) ? "-" : f2(a / b, "%.1fx"); }

// The floor row to compare a row with: a fleet floor of the same robot count, measured in
// phase 1 for phase 2, and in phase 4 for phase 4.
const Json* floor_for(const std::vector<Json>& rows, const Json& r) {
  const std::string ph = r["phase"] == "scaling" ? "scaling" : "floor";
  const Json* best = nullptr;
  for (const Json& f : rows)
    if (f["phase"] == ph && f["mode"] == "floor" && f["workload"] == "fleet" && f["robots"] == r["robots"]) best = &f;
  return best;
}

// The goals apply to answered requests: GetMap and SendGPS together (more samples than
// either alone, so that a p99 of a small fleet is not just its maximum).
double answered(const Json& r, const char* p) {
  const double v = num(r, {"answer_ms", "answered", p});
  return std::isnan(v) ? std::max(num(r, {"answer_ms", "GetMap", p}), num(r, {"answer_ms", "SendGPS", p})) : v;
}
double worst_p99(const Json& r) { return answered(r, "p99"); }
double worst_p50(const Json& r) { return answered(r, "p50"); }
// The fleet goal (docs/benchmarks.md): answered p99 <= 20 ms, every SendPos stored within 100 ms,
// nothing left unanswered.
bool fits(const Json& r) {
  return worst_p99(r) <= 20 && num(r, {"lag_ms", "SendPos", "le100"}) >= 1 && num(r, {"unanswered"}) == 0;
}

std::string row_name(const Json& r) {
  if (r["mode"] == "server") return std::to_string(r.value("server_procs", 1)) + " proc";
  return r["mode"].get<std::string>();  // floor, lean
}

// One table of fleet runs; the last column compares with the floor of the same size.
void fleet_table(const std::vector<Json>& rows, const std::vector<Json>& v) {
  std::printf("%-7s %6s %6s | %-17s %-17s | %-17s %7s | %6s %6s %6s %5s %5s | %s\n", "run", "robots", "req/s",
              "GetMap p50/p99", "SendGPS p50/p99", "SendPos lag", "<=100ms", "srv%", "db%", "rob%", "mach", "load",
              "x floor: GetMap p50,p99 SendGPS p50,p99 lag p50,p99");
  for (const Json& r : v) {
    std::string vs;
    if (r["mode"] != "floor")
      if (const Json* f = floor_for(rows, r)) {
        auto x = [&](const char* a, const char* k, const char* p) {
          return ratio(num(r, {a, k, p}), num(*f, {a, k, p}));
        };
        vs = x("answer_ms", "GetMap", "p50") + "," + x("answer_ms", "GetMap", "p99") + "  " +
             x("answer_ms", "SendGPS", "p50") + "," + x("answer_ms", "SendGPS", "p99") + "  " +
             x("lag_ms", "SendPos", "p50") + "," + x("lag_ms", "SendPos", "p99");
      }
    const double unans = num(r, {"unanswered"});
    if (unans > 0) vs += "  " + f2(unans, "%.0f") + " UNANSWERED";
    // srv%: fleetmap-server process(es), or this program's answering loop (floor, lean).
    const double srv = r["mode"] == "server" ? num(r, {"cpu", "server_pct"}) : num(r, {"cpu", "floor_answerer_pct"});
    std::printf("%-7s %6d %6.0f | %7s / %7s %7s / %7s | %7s / %7s %6s%% | %6s %6s %6s %5s %5s | %s\n",
                row_name(r).c_str(), r["robots"].get<int>(), num(r, {"rate_sent"}),
                ms(num(r, {"answer_ms", "GetMap", "p50"})).c_str(), ms(num(r, {"answer_ms", "GetMap", "p99"})).c_str(),
                ms(num(r, {"answer_ms", "SendGPS", "p50"})).c_str(), ms(num(r, {"answer_ms", "SendGPS", "p99"})).c_str(),
                ms(num(r, {"lag_ms", "SendPos", "p50"})).c_str(), ms(num(r, {"lag_ms", "SendPos", "p99"})).c_str(),
                f2(100 * num(r, {"lag_ms", "SendPos", "le100"}), "%.1f").c_str(), f2(srv, "%.0f").c_str(),
                f2(num(r, {"cpu", "db_pct"}), "%.0f").c_str(), f2(num(r, {"cpu", "robots_pct"}), "%.0f").c_str(),
                f2(num(r, {"cpu", "machine_pct"}), "%.0f").c_str(), f2(num(r, {"cpu", "load_start"}), "%.1f").c_str(),
                vs.c_str());
  }
}

void db_line(const char* what, const Json& r) {
  std::printf("  %-6s %5.0f req/s, rr backlog p50/max %s/%s rows, DB %s statements/s, %s COMMIT/s, %s fsyncs/s\n", what,
              num(r, {"rate_sent"}), f2(num(r, {"backlog", "p50"}), "%.0f").c_str(),
              f2(num(r, {"backlog", "max"}), "%.0f").c_str(),
              f2(num(r, {"cpu", "db_per_s", "Questions"}), "%.0f").c_str(),
              f2(num(r, {"cpu", "db_per_s", "Com_commit"}), "%.0f").c_str(),
              f2(num(r, {"cpu", "db_per_s", "Innodb_data_fsyncs"}), "%.0f").c_str());
}

void print_report(const std::string& file, const std::string& phase) {
  std::ifstream in(file);
  std::vector<Json> rows;
  for (std::string line; std::getline(in, line);)
    if (!line.empty()) rows.push_back(Json::parse(line));
  auto of = [&](const std::string& ph, const std::string& mode = "") {
    std::vector<Json> v;
    for (const Json& r : rows)
      if (r["phase"] == ph && (mode.empty() || r["mode"] == mode)) v.push_back(r);
    return v;
  };
  const bool all = phase == "all";
  const std::vector<Json> floors = of("floor");
  if (all || phase == "floor") {
    std::printf("\n== 1. Floor: the bare database path (robots -> rr -> minimal answering loop -> sa -> sa_mine)\n");
    for (const Json& r : floors)
      if (r["workload"] == "lone")
        std::printf(
            "lone robot (one request at a time): SendGPS answer p50 %s ms, p99 %s ms   (SPEC 9: p50 ~1.3, p99 ~2.3)\n",
            f2(num(r, {"answer_ms", "SendGPS", "p50"})).c_str(), f2(num(r, {"answer_ms", "SendGPS", "p99"})).c_str());
    std::vector<Json> fleet;
    for (const Json& r : floors)
      if (r["workload"] == "fleet") fleet.push_back(r);
    fleet_table(rows, fleet);
    const double poll = floors.empty() ? NAN : num(floors[0], {"wait", "min_ms"});
    const double mon = floors.empty() ? NAN : num(floors[0], {"monitor_ms"});
    std::printf(
        "(ms. Answer: INSERT start -> answer read; robots poll sa_mine every %g ms or more while an answer is\n"
        " due (the wait policy, --wait-*). SendPos lag: INSERT start -> rr row gone, monitor snapshot of rr every %g ms\n"
        " (+-%g ms). CPU in %% of one core: srv = fleetmap-server (or the answering loop for floor and lean),\n"
        " db = mariadbd, rob = the robots (this program), mach = whole machine incl. other users, of 200.)\n",
        poll, mon, mon / 2);
  }
  if (all || phase == "server") {
    std::printf(
        "\n== 2. The real server (1 process, default workers) beside the floor of phase 1; lean = a batched\n"
        "      prototype in fleetmap-loadgen doing the same durable work (see --mode lean)\n");
    const std::vector<Json> v = of("server");
    fleet_table(rows, v);
    for (const Json& r : v) {
      const Json* f = floor_for(rows, r);
      const double p50 = worst_p50(r), p99 = worst_p99(r);
      std::printf("%s at %d robots, answered requests: p50 <= 5 ms %s (%.2f), p99 <= 20 ms %s (%.2f)",
                  row_name(r).c_str(), r["robots"].get<int>(), p50 <= 5 ? "met" : "MISSED", p50,
                  p99 <= 20 ? "met" : "MISSED", p99);
      if (f) {
        const double f50 = worst_p50(*f), f99 = worst_p99(*f);
        std::printf(", <= 3x floor: p50 %s (%.1fx), p99 %s (%.1fx)", p50 <= 3 * f50 ? "met" : "MISSED", p50 / f50,
                    p99 <= 3 * f99 ? "met" : "MISSED", p99 / f99);
      }
      std::printf("\n");
      db_line(row_name(r).c_str(), r);
      if (f) db_line("floor", *f);
    }
  }
  if (all || phase == "idle") {
    std::printf("\n== 3. Idle: polling cost with no traffic, and a lone request, by --poll-max-ms\n");
    std::string lone = "-";
    for (const Json& r : floors)
      if (r["workload"] == "lone")
        lone = f2(num(r, {"answer_ms", "SendGPS", "p50"})) + " / " + f2(num(r, {"answer_ms", "SendGPS", "p99"}));
    std::printf("%11s | %9s %9s %8s | %-21s | %s\n", "poll_max_ms", "srv% idle", "db% idle", "stmts/s",
                "lone SendGPS p50/p99", "floor lone robot p50/p99");
    for (const Json& r : of("idle"))
      std::printf("%11s | %9s %9s %8s | %8s / %8s   | %s\n", f2(num(r, {"poll_max_ms"}), "%g").c_str(),
                  f2(num(r, {"idle_cpu", "server_pct"})).c_str(), f2(num(r, {"idle_cpu", "db_pct"})).c_str(),
                  f2(num(r, {"idle_cpu", "db_per_s", "Questions"}), "%.0f").c_str(),
                  f2(num(r, {"answer_ms", "SendGPS", "p50"})).c_str(),
                  f2(num(r, {"answer_ms", "SendGPS", "p99"})).c_str(), lone.c_str());
  }
  if (all || phase == "scaling") {
    std::printf("\n== 4. Scaling: robots x server processes (default workers each); a series stops when it falls behind\n");
    fleet_table(rows, of("scaling"));
    std::map<std::string, std::pair<int, int>> best;  // series -> (largest ok, smallest failing)
    for (const Json& r : of("scaling")) {
      auto& b = best.try_emplace(row_name(r), 0, 0).first->second;
      const int n = r["robots"].get<int>();
      if (fits(r))
        b.first = std::max(b.first, n);
      else if (!b.second || n < b.second)
        b.second = n;
    }
    for (auto& [series, b] : best)
      std::printf(
          "%-7s largest fleet with answered p99 <= 20 ms and every SendPos stored within 100 ms: %s%s   (target: 1000 "
          "robots, ~4700 req/s)\n",
          series.c_str(), b.first ? (std::to_string(b.first) + " robots").c_str() : "none",
          b.second ? (" (missed at " + std::to_string(b.second) + ")").c_str() : "");
  }
  if (all || phase == "policy") {
    // The robots' wait policy (protocol/wait_policy.h), one run each on the same server:
    // fleet rows give the answer latency, quiet rows (Alive and idle polls only) what an
    // idle robot costs mariadbd; the quiet row with idle polling off is their baseline.
    std::printf("\n== 5. Robot waiting policy: answered latency (fleet) and mariadbd CPU per idle robot (quiet)\n");
    std::printf("%-24s | %-27s | %17s | %6s %12s %12s %9s\n", "run", "first/min/max/backoff/idle", "answered p50/p99",
                "db %", "db %/robot", "polls/robot", "stmts/s");
    double quiet_base = NAN;
    for (const Json& r : of("policy"))
      if (r.value("workload", std::string()) == "quiet" && num(r, {"wait", "idle_ms"}) == 0)
        quiet_base = num(r, {"cpu", "db_pct"});
    for (const Json& r : of("policy")) {
      const bool quiet = r.value("workload", std::string()) == "quiet";
      const double n = r.value("robots", 1);
      const double db = num(r, {"cpu", "db_pct"});
      char wait[160];
      std::snprintf(wait, sizeof wait, "%g/%g/%g/%g/%g", num(r, {"wait", "first_poll_ms"}), num(r, {"wait", "min_ms"}),
                    num(r, {"wait", "max_ms"}), num(r, {"wait", "backoff"}), num(r, {"wait", "idle_ms"}));
      const std::string lat = quiet ? "-" : f2(num(r, {"answer_ms", "answered", "p50"})) + " / " +
                                                f2(num(r, {"answer_ms", "answered", "p99"}));
      const std::string per = f2(db / n, "%.3f") +
                              (quiet && !std::isnan(quiet_base) ? " (+" + f2((db - quiet_base) / n, "%.3f") + ")" : "");
      std::printf("%-24s | %-27s | %17s | %6s %12s %12s %9s\n", r.value("label", std::string()).c_str(), wait,
                  lat.c_str(), f2(db, "%.0f").c_str(), per.c_str(),
                  f2(num(r, {"robot_polls"}) / n, "%.0f").c_str(),
                  f2(num(r, {"cpu", "db_per_s", "Questions"}), "%.0f").c_str());
    }
    std::printf("(db %%/robot: mariadbd %% of one core / robots; in brackets, above the quiet run without idle polls.\n"
                " polls/robot: SELECTs on sa_mine per robot over the whole run, warm-up and drain included.)\n");
  }
}

}  // namespace

// ---------------------------------------------------------------------------------------

int main(int argc, char** argv) {
  using namespace fleetmap;
  CLI::App app{
      "fleetmap-loadgen: robots that speak RR/SA with plain SQL, for measuring fleetmap-server against the "
      "bare database path (driven by scripts/bench-server.sh)"};
  Options o;
  app.add_option("--mode", o.mode, "floor, server, lean, idle, report")
      ->check(CLI::IsMember({"floor", "server", "lean", "idle", "report"}))
      ->capture_default_str();
  app.add_option("--workload", o.workload, "fleet, quiet or lone")
      ->check(CLI::IsMember({"fleet", "quiet", "lone"}))
      ->capture_default_str();
  app.add_option("--robots", o.robots, "robots (accounts PREFIX0001...)")->capture_default_str();
  app.add_option("--first", o.first, "number of the first robot account")->capture_default_str();
  app.add_option("--prefix", o.prefix, "robot account name prefix")->capture_default_str();
  app.add_option("--password-dir", o.password_dir, "folder with NAME.pw for each robot (first line: password)");
  app.add_option("--threads", o.threads, "client threads multiplexing the robot connections")->capture_default_str();
  app.add_option("--seconds", o.seconds, "measurement window (idle: seconds of no traffic)")->capture_default_str();
  app.add_option("--warmup", o.warmup, "traffic before the window, s")->capture_default_str();
  app.add_option("--drain", o.drain, "after the window: wait this long for outstanding answers, s")
      ->capture_default_str();
  // The robots' wait policy: RobotClient's (protocol/wait_policy.h), field by field.
  app.add_option("--wait-first-poll-ms", o.wait.first_poll_ms, "first poll this long after an answered request's INSERT")
      ->capture_default_str();
  app.add_option("--wait-min-ms", o.wait.min_ms, "while an answer is due: shortest gap between polls")
      ->capture_default_str();
  app.add_option("--wait-max-ms", o.wait.max_ms, "while an answer is due: longest gap")->capture_default_str();
  app.add_option("--wait-backoff", o.wait.backoff, "while an answer is due: gap = this x time waited (0: fixed)")
      ->capture_default_str();
  app.add_option("--wait-idle-ms", o.wait.idle_ms, "nothing due: poll this often (pushed ops); 0: never")
      ->capture_default_str();
  app.add_option("--monitor-ms", o.monitor_ms, "rr snapshot period for the processing lag; 0: off")
      ->capture_default_str();
  app.add_option("--pos-hz", o.pos_hz, "SendPos rate per robot")->capture_default_str();
  app.add_option("--map-period", o.map_period_s, "GetMap period per robot, s")->capture_default_str();
  app.add_option("--gps-period", o.gps_period_s, "SendGPS period per robot, s")->capture_default_str();
  app.add_option("--alive-period", o.alive_period_s, "Alive period (server mode: the one Start tells)")
      ->capture_default_str();
  app.add_option("--window", o.window_m, "GetMap window side, m")->capture_default_str();
  app.add_option("--map", o.map, "the robots' map (for its border)")->capture_default_str();
  app.add_option("--lone-count", o.lone_count, "lone workload: requests")->capture_default_str();
  app.add_option("--floor-threads", o.floor_threads, "floor: answering threads (each busy-polls)")
      ->capture_default_str();
  app.add_option("--floor-batch", o.floor_batch, "floor and lean: rr rows per transaction")->capture_default_str();
  app.add_option("--lean-threads", o.lean_threads, "lean: answering threads (back-off polling as the server's)")
      ->capture_default_str();
  app.add_option("--connect-concurrency", o.connect_concurrency, "connects in flight per client thread")
      ->capture_default_str();
  app.add_flag("--robot-socket", o.robot_socket, "robots connect over the unix socket (default TCP, as real robots)");
  app.add_option("--server-pid", o.server_pids, "fleetmap-server pid(s) for CPU use")->delimiter(',');
  app.add_option("--db-pid", o.db_pid, "mariadbd pid for CPU use");
  app.add_option("--server-procs", o.server_procs, "recorded: server processes");
  app.add_option("--workers", o.workers, "recorded: workers per server process");
  app.add_option("--poll-max-ms", o.poll_max_ms, "recorded: the servers' --poll-max-ms");
  app.add_option("--phase", o.phase, "recorded: table this run belongs to (floor, server, idle, scaling, policy)");
  app.add_option("--label", o.label, "recorded: row label");
  app.add_option("--results", o.results, "append the run's figures as one JSON line to this file");
  app.add_option("--config", o.config, "config file (default: FLEETMAP_CONFIG, FLEETMAP_HOME/fleetmap.conf, ...)");
  app.add_option("--seed", o.seed, "random seed")->capture_default_str();
  CLI11_PARSE(app, argc, argv);

  if (o.mode == "report") {
    if (o.results.empty()) {
      std::fprintf(stderr, "loadgen: --mode report needs --results FILE\n");
      return 64;
    }
    print_report(o.results, o.phase == "adhoc" ? "all" : o.phase);
    return 0;
  }
  if (o.mode == "idle") o.workload = "lone";
  if (o.workload == "lone") o.robots = 1;
  if (o.label.empty()) o.label = o.mode + "/" + o.workload;
  if (o.password_dir.empty()) {
    std::fprintf(stderr, "loadgen: --password-dir is required\n");
    return 64;
  }
  {  // one socket per robot, and more
    rlimit l{};
    getrlimit(RLIMIT_NOFILE, &l);
    l.rlim_cur = l.rlim_max;
    setrlimit(RLIMIT_NOFILE, &l);
  }
  mysql_library_init(0, nullptr, nullptr);

  try {
    const DbSettings server_db = load_settings(Role::Server, o.config);
    const DbSettings operator_db = load_settings(Role::Operator, o.config);
    Shared sh(o);
    sh.host = server_db.host;
    sh.port = server_db.port;
    sh.socket = server_db.socket;
    sh.database = server_db.database;
    {
      auto c = connect(operator_db);
      mysqlpp::Query q = c->query();
      q << "SELECT mx1, my1, mx4, my4 FROM maps WHERE name = " << mysqlpp::quote << o.map;
      const mysqlpp::StoreQueryResult r = q.store();
      if (r.empty()) throw std::runtime_error("no map named '" + o.map + "'");
      const double x1 = r[0][0], y1 = r[0][1], x4 = r[0][2], y4 = r[0][3];
      sh.bounds = {std::min(x1, x4), std::min(y1, y4), std::max(x1, x4), std::max(y1, y4)};
    }
    auto status = connect(server_db);
    Json out;
    out["phase"] = o.phase;
    out["label"] = o.label;
    out["mode"] = o.mode;
    out["workload"] = o.workload;
    out["robots"] = o.robots;
    out["threads"] = o.threads;
    if (o.server_procs) out["server_procs"] = o.server_procs;
    if (o.workers) out["workers"] = o.workers;
    if (o.poll_max_ms >= 0) out["poll_max_ms"] = o.poll_max_ms;
    out["wait"] = {{"first_poll_ms", o.wait.first_poll_ms}, {"min_ms", o.wait.min_ms}, {"max_ms", o.wait.max_ms},
                   {"backoff", o.wait.backoff}, {"idle_ms", o.wait.idle_ms}};
    out["monitor_ms"] = o.monitor_ms;

    if (o.mode == "idle") {
      // No robot connected: what the servers and the database burn on polling alone.
      std::printf("idle: %g s with no traffic ...\n", o.seconds);
      std::fflush(stdout);
      const Snapshot a = snapshot(o, status.get());
      std::this_thread::sleep_for(from_ms(o.seconds * 1000));
      const Snapshot b = snapshot(o, status.get());
      out["idle_cpu"] = cpu_between(a, b, 0);
      std::printf("idle: servers %s%% of a core, mariadbd %s%%, %s statements/s\n",
                  fmt(out["idle_cpu"], "server_pct").c_str(), fmt(out["idle_cpu"], "db_pct").c_str(),
                  f2(num(out, {"idle_cpu", "db_per_s", "Questions"}), "%.0f").c_str());
    }

    // Robots
    std::vector<Robot> robots(o.robots);
    std::mt19937 rng(o.seed);
    for (int i = 0; i < o.robots; ++i) {
      Robot& r = robots[i];
      char name[64];
      std::snprintf(name, sizeof name, "%s%04d", o.prefix.c_str(), o.first + i);
      r.name = name;
      std::ifstream pw(o.password_dir + "/" + r.name + ".pw");
      if (!std::getline(pw, r.password))
        throw std::runtime_error("no password file " + o.password_dir + "/" + r.name + ".pw");
      r.rng.seed(o.seed * 7919 + i);
      const Bounds& m = sh.bounds;
      std::uniform_real_distribution<double> ux(m.xmin + 60, std::max(m.xmin + 61, m.xmax - 60)),
          uy(m.ymin + 60, std::max(m.ymin + 61, m.ymax - 60)), ut(-M_PI, M_PI);
      r.x = ux(rng);
      r.y = uy(rng);
      r.theta = ut(rng);
      r.alive_s = o.alive_period_s;
    }
    const int nthreads = std::max(1, std::min(o.threads, o.robots));
    std::vector<std::vector<Robot*>> parts(nthreads);
    for (int i = 0; i < o.robots; ++i) parts[i % nthreads].push_back(&robots[i]);

    // Helpers: floor answerers, monitor
    std::vector<std::thread> helpers;
    std::vector<double> answerer_cpu(o.mode == "floor" ? o.floor_threads : o.mode == "lean" ? o.lean_threads : 0, 0);
    std::vector<uint64_t> answerer_handled(answerer_cpu.size(), 0), answerer_empty(answerer_cpu.size(), 0);
    for (size_t i = 0; i < answerer_cpu.size(); ++i)
      helpers.emplace_back([&, i] {
        if (o.mode == "lean")
          lean_answerer(sh, server_db, answerer_cpu[i], answerer_handled[i], answerer_empty[i]);
        else
          floor_answerer(sh, server_db, answerer_cpu[i], answerer_handled[i], answerer_empty[i]);
      });

    const TimePoint t_setup = Clock::now();
    std::vector<std::unique_ptr<RobotThread>> rts;
    std::vector<std::thread> threads;
    for (auto& p : parts) rts.push_back(std::make_unique<RobotThread>(sh, p));
    for (auto& rt : rts) threads.emplace_back([&rt] { rt->run(); });

    // Set-up: connected, old answers cleared, and (server) registered with Ready.
    const TimePoint setup_deadline = Clock::now() + std::chrono::seconds(180);
    while (sh.setup_done.load() + sh.failed.load() < o.robots && Clock::now() < setup_deadline)
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    const double setup_s = ms_between(t_setup, Clock::now()) / 1000;
    if (sh.failed.load() > 0 || sh.setup_done.load() < o.robots)
      std::fprintf(stderr, "loadgen: %d of %d robots failed to set up\n", o.robots - sh.setup_done.load(), o.robots);
    std::printf("%s: %d robots set up in %.1f s (%s) on %d client threads\n", o.label.c_str(), sh.setup_done.load(),
                setup_s, o.mode == "server" ? "connect + Ready" : "connect", nthreads);
    std::fflush(stdout);
    out["setup_s"] = setup_s;

    Stats mon_stats;
    Samples backlog;
    uint64_t mon_queries = 0;
    sh.t_go = Clock::now() + (o.workload == "lone" ? std::chrono::milliseconds(1000) : std::chrono::milliseconds(0));
    sh.m_start = o.workload == "lone" ? sh.t_go : sh.t_go + from_ms(o.warmup * 1000);
    sh.m_end = o.workload == "lone" ? sh.t_go + std::chrono::hours(1) : sh.m_start + from_ms(o.seconds * 1000);
    sh.drain_end = o.workload == "lone" ? sh.m_end : sh.m_end + from_ms(o.drain * 1000);
    if (o.mode != "idle" && o.monitor_ms > 0)
      helpers.emplace_back([&] { monitor(sh, server_db, mon_stats, backlog, mon_queries, rts.size()); });
    sh.go.store(true, std::memory_order_release);

    Snapshot a, b;
    bool sampled = false;
    if (o.workload != "lone") {
      std::this_thread::sleep_until(sh.m_start);
      a = snapshot(o, status.get());
      std::this_thread::sleep_until(sh.m_end);
      b = snapshot(o, status.get());
      sampled = true;
    } else {
      a = snapshot(o, status.get());
    }
    for (auto& t : threads) t.join();
    if (!sampled) b = snapshot(o, status.get());
    sh.stop_helpers = true;
    for (auto& t : helpers) t.join();

    Stats total;
    for (auto& rt : rts) total.merge(rt->stats);
    total.merge(mon_stats);
    double ans_cpu = 0;
    uint64_t handled = 0, empty = 0;
    for (size_t i = 0; i < answerer_cpu.size(); ++i) {
      ans_cpu += answerer_cpu[i];
      handled += answerer_handled[i];
      empty += answerer_empty[i];
    }
    const double window_s = o.workload != "lone" ? o.seconds : ms_between(sh.m_start, b.t) / 1000;
    out["window_s"] = window_s;
    out["cpu"] = cpu_between(a, b, ans_cpu);
    uint64_t sent = 0, unanswered = 0;
    Json answer, lag, insert, slip, counts;
    for (int k = 0; k < kKinds; ++k) {
      KindStats& s = total.kind[k];
      sent += s.sent;
      unanswered += s.unanswered;
      if (s.sent == 0) continue;
      counts[kKindName[k]] = {
          {"sent", s.sent}, {"answered", s.answered}, {"errors", s.errors}, {"unanswered", s.unanswered}};
      if (!s.latency.v.empty()) answer[kKindName[k]] = s.latency.summary();
      if (!s.lag.v.empty()) lag[kKindName[k]] = s.lag.summary();
      insert[kKindName[k]] = s.insert.summary();
      slip[kKindName[k]] = s.slip.summary();
    }
    out["sent"] = sent;
    out["rate_sent"] = sent / window_s;
    out["unanswered"] = unanswered;
    out["counts"] = counts;
    {
      Samples all;
      all.merge(total.kind[kGetMap].latency);
      all.merge(total.kind[kSendGps].latency);
      if (!all.v.empty()) answer["answered"] = all.summary();
    }
    out["answer_ms"] = answer;
    out["lag_ms"] = lag;
    out["insert_ms"] = insert;
    out["slip_ms"] = slip;
    out["backlog"] = backlog.summary();
    out["robot_polls"] = total.polls;
    out["robot_deletes"] = total.deletes;
    out["unsolicited"] = total.unsolicited;
    out["insert_errors"] = total.insert_errors;
    out["query_errors"] = total.query_errors;
    out["monitor_queries"] = mon_queries;
    if (!total.error_codes.empty()) out["error_codes"] = total.error_codes;
    if (o.mode == "floor" || o.mode == "lean")
      out["answerer"] = {
          {"handled", handled}, {"empty_polls", empty}, {"threads", answerer_cpu.size()}, {"batch", o.floor_batch}};

    // Human-readable summary of this run
    std::printf("%s: %.0f requests/s sent over %.1f s (%llu requests)", o.label.c_str(), sent / window_s, window_s,
                static_cast<unsigned long long>(sent));
    if (unanswered) std::printf(", %llu UNANSWERED", static_cast<unsigned long long>(unanswered));
    if (total.insert_errors || total.query_errors)
      std::printf(", %llu insert and %llu query errors", static_cast<unsigned long long>(total.insert_errors),
                  static_cast<unsigned long long>(total.query_errors));
    std::printf("\n");
    for (int k = 0; k < kKinds; ++k) {
      const char* n = kKindName[k];
      if (!counts.contains(n)) continue;
      std::printf("  %-8s sent %6llu", n, static_cast<unsigned long long>(total.kind[k].sent));
      if (answer.contains(n))
        std::printf("  answer p50 %6s p99 %6s ms", fmt(answer[n], "p50").c_str(), fmt(answer[n], "p99").c_str());
      if (lag.contains(n))
        std::printf("  rr lag p50 %6s p99 %6s ms", fmt(lag[n], "p50").c_str(), fmt(lag[n], "p99").c_str());
      std::printf("  insert p50 %5s p99 %6s ms  slip p99 %6s ms", fmt(insert[n], "p50").c_str(),
                  fmt(insert[n], "p99").c_str(), fmt(slip[n], "p99").c_str());
      if (total.kind[k].errors) std::printf("  %llu errors", static_cast<unsigned long long>(total.kind[k].errors));
      std::printf("\n");
    }
    for (auto& [c, n] : total.error_codes)
      std::printf("  error answers %s: %llu\n", c.c_str(), static_cast<unsigned long long>(n));
    const Json& cpu = out["cpu"];
    std::printf(
        "  CPU %% of one core: servers %s, mariadbd %s, robots (this program) %s%s, machine %s of %s; DB %s "
        "statements/s, %s COMMITs/s, %s fsyncs/s\n",
        fmt(cpu, "server_pct", "%.1f").c_str(), fmt(cpu, "db_pct", "%.1f").c_str(),
        fmt(cpu, "robots_pct", "%.1f").c_str(),
        answerer_cpu.empty() ? "" : (", " + o.mode + " answerer " + fmt(cpu, "floor_answerer_pct", "%.1f")).c_str(),
        fmt(cpu, "machine_pct", "%.0f").c_str(), f2(100 * num(cpu, {"cores"}), "%.0f").c_str(),
        f2(num(cpu, {"db_per_s", "Questions"}), "%.0f").c_str(),
        f2(num(cpu, {"db_per_s", "Com_commit"}), "%.0f").c_str(),
        f2(num(cpu, {"db_per_s", "Innodb_data_fsyncs"}), "%.0f").c_str());
    if (answer.contains("answered"))
      std::printf("  answered (GetMap+SendGPS): p50 %s p99 %s ms\n", fmt(answer["answered"], "p50").c_str(),
                  fmt(answer["answered"], "p99").c_str());
    if (lag.contains("SendPos"))
      std::printf("  SendPos stored within 100 ms: %s %% (max %s ms); load average %s at the start, %s at the end\n",
                  f2(100 * num(lag, {"SendPos", "le100"}), "%.2f").c_str(), fmt(lag["SendPos"], "max").c_str(),
                  f2(num(cpu, {"load_start"}), "%.1f").c_str(), f2(num(cpu, {"load_end"}), "%.1f").c_str());
    if (!backlog.v.empty())
      std::printf("  rr backlog seen by the monitor: p50 %s, max %s rows (%llu snapshots)\n",
                  fmt(out["backlog"], "p50", "%.0f").c_str(), fmt(out["backlog"], "max", "%.0f").c_str(),
                  static_cast<unsigned long long>(mon_queries));
    std::fflush(stdout);
    if (!o.results.empty()) {
      std::ofstream f(o.results, std::ios::app);
      f << out.dump() << "\n";
    }
    return (sh.failed.load() > 0) ? 1 : 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "loadgen: %s\n", e.what());
    return 1;
  }
}
