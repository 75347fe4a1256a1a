// The request loop under load and under abuse (SPEC 5.3), against the real fleetmap-server
// processes and MariaDB, with robots that speak plain SQL:
//   * two server processes share one fleet: every request answered exactly once, in order
//     per robot, never to another robot, and both processes did work;
//   * SIGKILL at random moments, again and again, while robots keep sending: no request
//     lost, none answered twice, side effects stored once, order kept;
//   * a robot that holds locks on its answers (SELECT ... FOR UPDATE, DELETE, or a
//     SERIALIZABLE read of sa_mine in an open transaction) blocks no other robot's answers
//     and, when the server's answer to it waits, does not stall the others: the server
//     ends that robot's connection and says so in its log;
//   * SIGTERM while requests flow: exit code 0 within seconds, nothing half-handled, and
//     the next server answers the rest exactly once.
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <map>
#include <mutex>
#include <random>
#include <regex>
#include <set>
#include <sstream>
#include <thread>

#include <gtest/gtest.h>

#include "tests/integration/server_fixture.h"
#include "tests/integration/test_db.h"

namespace fleetmap::test {
namespace {

using Clock = std::chrono::steady_clock;
using std::chrono::milliseconds;
using std::chrono::seconds;

constexpr const char* kMap = "conc_map";

double elapsed_s(Clock::time_point since) { return std::chrono::duration<double>(Clock::now() - since).count(); }

// A fleetmap-server child that keeps its exit status (ServerProcess drops it) and never
// outlives the test: the destructor SIGKILLs what is still running.
class Daemon {
 public:
  Daemon(const std::string& flags, const std::string& log_name)
      : log_path_(temp_path(log_name)), pid_(spawn_server(flags, log_path_)) {}
  ~Daemon() {
    if (pid_ > 0) {
      ::kill(pid_, SIGKILL);
      waitpid(pid_, nullptr, 0);
    }
  }
  // Sends sig and waits up to timeout. Returns the wait status, or nullopt when the
  // process was still running then (it is SIGKILLed so the test does not hang).
  std::optional<int> signal_and_wait(int sig, milliseconds timeout) {
    if (pid_ <= 0) return std::nullopt;
    ::kill(pid_, sig);
    const auto until = Clock::now() + timeout;
    int status = 0;
    while (Clock::now() < until) {
      if (waitpid(pid_, &status, WNOHANG) == pid_) {
        pid_ = -1;
        return status;
      }
      std::this_thread::sleep_for(milliseconds(5));
    }
    ::kill(pid_, SIGKILL);
    waitpid(pid_, nullptr, 0);
    pid_ = -1;
    return std::nullopt;
  }
  std::string log() const { return read_file(log_path_); }
  Daemon(const Daemon&) = delete;
  Daemon& operator=(const Daemon&) = delete;

 private:
  std::string log_path_;  // before pid_: the constructor starts the process with it
  pid_t pid_ = -1;
};

// Logs are appended to (ServerProcess, Daemon): start each test with an empty one.
void fresh_log(const std::string& name) { write_file(temp_path(name), ""); }

// Robot accounts made for one test only are removed at its end, also when it fails early.
// The answers an op gets, in order (SPEC 5.2). The ops used here always get an answer.
std::vector<std::string> expected_answers(const std::string& op) {
  if (op == "Ready") return {"Start", "SetMap"};
  if (op == "SendGPS") return {"OpAck"};
  if (op == "GetPosIni") return {"SetPosIni"};
  if (op == "GetPosEnd") return {"Error"};  // no goal: no_goal, which the server logs at debug level
  throw std::logic_error("no expectation for " + op);
}

struct Sent {
  unsigned long long id = 0;
  std::string op;
};

struct Ans {
  unsigned long long id = 0;
  unsigned robot_id = 0;
  std::optional<unsigned long long> request_id;
  std::string op;
};

// One robot account and the traffic its thread produced.
struct Bot {
  std::string name;
  std::string password;
  unsigned id = 0;
  std::vector<Sent> sent;
  std::vector<Ans> received;  // when the robot reads its own answers
  size_t gps_sent = 0;
  long long gps_before = 0;   // gps_fixes rows of this robot before the test (a re-added robot keeps its history)
  std::string error;          // an exception in the robot's thread
};

std::vector<Bot> make_bots(const std::string& prefix, int n, bool pose_ini) {
  ensure_example_map(kMap);
  std::vector<Bot> bots(n);
  for (int i = 0; i < n; ++i) {
    Bot& b = bots[i];
    b.name = prefix + std::to_string(i);
    b.password = add_robot(b.name, kMap);
    b.id = static_cast<unsigned>(scalar("SELECT id FROM robots WHERE db_user = '" + b.name + "'"));
    if (pose_ini) {
      RunResult r = run("fleetmap", "pose-ini " + b.name + " 3 4 1.5");
      if (r.exit_code != 0) throw std::runtime_error("pose-ini " + b.name + ": " + r.err);
    }
    b.gps_before = scalar("SELECT COUNT(*) FROM gps_fixes WHERE robot_id = " + std::to_string(b.id));
  }
  return bots;
}

std::string in_list(const std::vector<Bot>& bots) {
  std::string s;
  for (const Bot& b : bots) s += (s.empty() ? "'" : ", '") + b.name + "'";
  return "(" + s + ")";
}

long long waiting_requests(const std::vector<Bot>& bots) {
  return scalar("SELECT COUNT(*) FROM rr WHERE db_user IN " + in_list(bots));
}

// The i-th request of a robot in the mixes below: mostly SendGPS (OpAck, and a stored fix
// whose lat says which request it was), some GetPosIni (SetPosIni), some GetPosEnd (Error
// no_goal, logged by the server with the request id: tells which process handled it).
std::pair<std::string, std::string> mixed_request(size_t i, Bot& b) {
  switch (i % 10) {
    case 3:
      return {"GetPosEnd", "{}"};
    case 1:
    case 6:
      return {"GetPosIni", "{}"};
    default: {
      ++b.gps_sent;
      std::ostringstream p;
      p.precision(17);
      p << R"({"lat": )" << 0.001 * static_cast<double>(i) << R"(, "lon": )" << b.id % 90 << "}";
      return {"SendGPS", p.str()};
    }
  }
}

std::vector<Ans> answers_in_sa(mysqlpp::Connection& db, const Bot& b) {
  mysqlpp::Query q = db.query();
  q << "SELECT id, robot_id, request_id, op FROM sa WHERE sentinel = 0 AND db_user = " << mysqlpp::quote << b.name << " ORDER BY id";
  std::vector<Ans> out;
  for (const mysqlpp::Row& r : q.store()) {
    Ans a;
    a.id = std::stoull(std::string(r[0]));
    a.robot_id = static_cast<unsigned>(std::stoul(std::string(r[1])));
    if (!r[2].is_null()) a.request_id = std::stoull(std::string(r[2]));
    a.op = std::string(r[3]);
    out.push_back(std::move(a));
  }
  return out;
}

std::set<unsigned long long> waiting_ids(mysqlpp::Connection& db, const Bot& b) {
  mysqlpp::Query q = db.query();
  q << "SELECT id FROM rr WHERE db_user = " << mysqlpp::quote << b.name;
  std::set<unsigned long long> out;
  for (const mysqlpp::Row& r : q.store()) out.insert(std::stoull(std::string(r[0])));
  return out;
}

// Checks one robot's answers (in sa id order) against what it sent. With complete, every
// request must be answered; otherwise the answered requests must be a prefix of the sent
// ones (the server takes a robot's requests in id order) and the rest must be exactly
// `still_waiting` (the robot's rows in rr). Returns the problems found (at most a few).
std::vector<std::string> check_answers(const Bot& b, const std::vector<Ans>& answers, bool complete,
                                       const std::set<unsigned long long>& still_waiting = {}) {
  std::vector<std::string> problems;
  auto problem = [&](const std::string& p) {
    if (problems.size() < 8) problems.push_back(b.name + ": " + p);
  };
  std::map<unsigned long long, size_t> index;  // request id -> position in sent
  for (size_t i = 0; i < b.sent.size(); ++i) {
    if (i > 0 && b.sent[i].id <= b.sent[i - 1].id) problem("request ids not increasing at " + std::to_string(i));
    index[b.sent[i].id] = i;
  }
  std::vector<std::vector<std::string>> got(b.sent.size());
  unsigned long long last_sa = 0;
  size_t last_req = 0;
  for (const Ans& a : answers) {
    const std::string where = "answer " + std::to_string(a.id);
    if (a.id <= last_sa) problem(where + " out of sa id order");
    last_sa = a.id;
    if (a.robot_id != b.id) problem(where + " addressed to robot " + std::to_string(a.robot_id));
    if (!a.request_id) {
      problem(where + " (" + a.op + ") has no request_id");
      continue;
    }
    auto it = index.find(*a.request_id);
    if (it == index.end()) {
      problem(where + " answers request " + std::to_string(*a.request_id) + ", which this robot did not send");
      continue;
    }
    if (it->second < last_req)
      problem(where + " answers request " + std::to_string(*a.request_id) + " after an answer to a later request " +
              std::to_string(b.sent[last_req].id));
    last_req = std::max(last_req, it->second);
    got[it->second].push_back(a.op);
  }
  bool gap = false;
  for (size_t i = 0; i < b.sent.size(); ++i) {
    const Sent& s = b.sent[i];
    const std::string what = "request " + std::to_string(s.id) + " (" + s.op + ")";
    const bool waiting = still_waiting.count(s.id) > 0;
    if (got[i].empty()) {
      if (complete) problem(what + " never answered");
      else if (!waiting) problem(what + " neither answered nor in rr: lost");
      gap = true;
      continue;
    }
    if (waiting) problem(what + " answered but still in rr: it would be answered again");
    if (gap) problem(what + " answered while an earlier request was not");
    const std::vector<std::string> want = expected_answers(s.op);
    if (got[i] != want) {
      std::string g;
      for (const auto& o : got[i]) g += o + " ";
      problem(what + " got answers [ " + g + "], " + std::to_string(got[i].size()) + " instead of " +
              std::to_string(want.size()));
    }
  }
  for (unsigned long long w : still_waiting)
    if (!index.count(w)) problem("rr holds request " + std::to_string(w) + ", which this robot did not send");
  return problems;
}

// Every request of every robot answered exactly once, in order, stored once (gps_fixes),
// nothing left in rr; read with the administrator's connection.
void expect_all_answered_once(const std::vector<Bot>& bots) {
  auto db = admin();
  size_t requests = 0, answers = 0;
  for (const Bot& b : bots) {
    EXPECT_TRUE(b.error.empty()) << b.name << ": " << b.error;
    const std::vector<Ans> got = answers_in_sa(*db, b);
    for (const std::string& p : check_answers(b, got, true)) ADD_FAILURE() << p;
    EXPECT_TRUE(waiting_ids(*db, b).empty()) << b.name << " still has requests in rr";
    const long long fixes = scalar("SELECT COUNT(*) FROM gps_fixes WHERE robot_id = " + std::to_string(b.id));
    EXPECT_EQ(fixes - b.gps_before, static_cast<long long>(b.gps_sent)) << b.name << ": SendGPS stored not exactly once";
    requests += b.sent.size();
    answers += got.size();
  }
  std::cout << "[ info ] " << bots.size() << " robots, " << requests << " requests, " << answers << " answers checked\n";
}

// Request ids the server logged as handled with an Error (debug level): "request <id> (GetPosEnd)".
std::set<unsigned long long> logged_requests(const std::string& log) {
  static const std::regex re(R"(request (\d+) \(GetPosEnd\): no_goal)");
  std::set<unsigned long long> out;
  for (auto it = std::sregex_iterator(log.begin(), log.end(), re); it != std::sregex_iterator(); ++it)
    out.insert(std::stoull((*it)[1]));
  return out;
}

// ---------------------------------------------------------------------------------------
// a. Two server processes, 20 robots, 5 000 requests.

TEST(ServerConcurrency, TwoServersAnswerEveryRequestOnceInOrder) {
  constexpr int kRobots = 20;
  constexpr size_t kRequests = 250;
  std::vector<Bot> bots = make_bots("conc_r", kRobots, true);
  fresh_log("conc_server1.log");
  fresh_log("conc_server2.log");
  const auto t0 = Clock::now();
  auto s1 = std::make_unique<ServerProcess>("--workers 2", "conc_server1.log");
  auto s2 = std::make_unique<ServerProcess>("--workers 2", "conc_server2.log");

  std::vector<std::thread> threads;
  for (Bot& b : bots) {
    threads.emplace_back([&b, t0] {
      try {
        SqlRobot robot(b.name, b.password);
        auto take = [&] {
          for (const SqlAnswer& a : robot.peek()) {
            mysqlpp::Query d = robot.connection().query();
            d << "DELETE FROM sa_mine WHERE id = " << a.id;
            d.execute();
            b.received.push_back({a.id, a.robot_id, a.request_id, a.op});
          }
        };
        b.sent.push_back({robot.send("Ready", R"({"magic": 77})"), "Ready"});
        for (const SqlAnswer& a : robot.receive(2, seconds(15))) b.received.push_back({a.id, a.robot_id, a.request_id, a.op});
        if (b.received.size() != 2) throw std::runtime_error("no Start + SetMap");
        for (size_t i = 0; i < kRequests; ++i) {
          auto [op, params] = mixed_request(i, b);
          b.sent.push_back({robot.send(op, params), op});
          if (i % 8 == 7) take();  // read and delete answers while sending
        }
        const size_t want = kRequests + 2;
        const auto until = t0 + seconds(45);  // one deadline for all: the test stays under a minute
        while (b.received.size() < want && Clock::now() < until) {
          take();
          if (b.received.size() < want) std::this_thread::sleep_for(milliseconds(10));
        }
        take();  // anything beyond (a double answer) shows up in the check
      } catch (const std::exception& e) {
        b.error = e.what();
      }
    });
  }
  for (auto& t : threads) t.join();
  const double run_s = elapsed_s(t0);
  s1.reset();
  s2.reset();

  size_t total = 0;
  std::map<unsigned long long, std::string> owner;  // request id -> the robot that sent it
  for (const Bot& b : bots)
    for (const Sent& s : b.sent) owner[s.id] = b.name;
  for (const Bot& b : bots) {
    EXPECT_TRUE(b.error.empty()) << b.name << ": " << b.error;
    // Each request answered exactly once, with the right ops, in order, to this robot.
    for (const std::string& p : check_answers(b, b.received, true)) ADD_FAILURE() << p;
    for (const Ans& a : b.received)
      if (a.request_id && owner.count(*a.request_id) && owner[*a.request_id] != b.name)
        ADD_FAILURE() << b.name << " got answer " << a.id << " to request " << *a.request_id << " of "
                      << owner[*a.request_id];
    total += b.sent.size() - 1;  // without the Ready
  }
  EXPECT_EQ(total, kRobots * kRequests);
  // Nothing left behind: every answer was read and deleted by its robot, every request taken.
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM sa WHERE sentinel = 0 AND db_user IN " + in_list(bots)), 0);
  EXPECT_EQ(waiting_requests(bots), 0);
  for (const Bot& b : bots) {
    const long long fixes = scalar("SELECT COUNT(*) FROM gps_fixes WHERE robot_id = " + std::to_string(b.id));
    EXPECT_EQ(fixes - b.gps_before, static_cast<long long>(b.gps_sent)) << b.name;
  }

  // Both processes did work: each logged some of the GetPosEnd requests it answered.
  const std::string log1 = read_file(temp_path("conc_server1.log"));
  const std::string log2 = read_file(temp_path("conc_server2.log"));
  const std::set<unsigned long long> by1 = logged_requests(log1), by2 = logged_requests(log2);
  std::set<unsigned long long> get_pos_end;
  for (const Bot& b : bots)
    for (const Sent& s : b.sent)
      if (s.op == "GetPosEnd") get_pos_end.insert(s.id);
  std::set<unsigned long long> both;
  std::set_union(by1.begin(), by1.end(), by2.begin(), by2.end(), std::inserter(both, both.end()));
  EXPECT_GT(by1.size(), 0u) << "server 1 answered none of the GetPosEnd requests";
  EXPECT_GT(by2.size(), 0u) << "server 2 answered none of the GetPosEnd requests";
  EXPECT_EQ(both, get_pos_end) << "the logs do not account for every GetPosEnd";
  static const std::regex error_line(R"(\d error )");  // spdlog level "error"
  EXPECT_FALSE(std::regex_search(log1, error_line)) << log1.substr(0, 4000);
  EXPECT_FALSE(std::regex_search(log2, error_line)) << log2.substr(0, 4000);
  std::cout << "[ info ] " << total << " requests answered in " << run_s << " s; GetPosEnd handled by server 1: "
            << by1.size() << ", by server 2: " << by2.size() << " (of " << get_pos_end.size() << ")\n";
  if (HasFailure()) std::cerr << "server 1 log (head):\n" << log1.substr(0, 6000) << "\nserver 2 log (head):\n" << log2.substr(0, 6000);
}

// ---------------------------------------------------------------------------------------
// Robots that send continuously until told to stop, without reading their answers (the
// checks read sa with the administrator's connection).

class TrafficGenerator {
 public:
  TrafficGenerator(std::vector<Bot>& bots, milliseconds pause) : bots_(bots) {
    for (Bot& b : bots_) threads_.emplace_back([this, &b, pause] { run(b, pause); });
  }
  ~TrafficGenerator() { stop(); }
  void stop() {
    stop_ = true;
    for (auto& t : threads_)
      if (t.joinable()) t.join();
  }
  size_t sent() const { return sent_; }

 private:
  void run(Bot& b, milliseconds pause) {
    try {
      SqlRobot robot(b.name, b.password);
      b.sent.push_back({robot.send("Ready", R"({"magic": 5})"), "Ready"});
      for (size_t i = 0; !stop_; ++i) {
        auto [op, params] = mixed_request(i, b);
        b.sent.push_back({robot.send(op, params), op});
        ++sent_;
        std::this_thread::sleep_for(pause);
      }
    } catch (const std::exception& e) {
      b.error = e.what();
    }
  }
  std::vector<Bot>& bots_;
  std::vector<std::thread> threads_;
  std::atomic<bool> stop_{false};
  std::atomic<size_t> sent_{0};
};

// ---------------------------------------------------------------------------------------
// Fairness under saturation: the longest-waiting robots are served first (RequestQueue::
// waiting_accounts orders by the oldest request). A server that takes fewer robots per
// pass than have work must still get to every one of them, not always to the same few.

TEST(ServerConcurrency, BusyRobotsDoNotStarveOthers) {
  constexpr int kRobots = 6;
  std::vector<Bot> bots = make_bots("fair_r", kRobots, true);
  fresh_log("fair_server.log");
  auto server = std::make_unique<ServerProcess>("--workers 1 --batch-robots 2 --batch-requests 4", "fair_server.log");
  std::map<std::string, double> oldest_s;  // age of each robot's oldest waiting request
  std::map<std::string, long long> answered;
  {
    TrafficGenerator traffic(bots, milliseconds(1));
    std::this_thread::sleep_for(seconds(3));
    auto db = admin();
    mysqlpp::Query q = db->query("SELECT db_user, TIMESTAMPDIFF(MICROSECOND, MIN(created_at), SYSDATE(6)) FROM rr "
                                 "WHERE db_user IN " + in_list(bots) + " GROUP BY db_user");
    for (const mysqlpp::Row& r : q.store()) oldest_s[std::string(r[0])] = std::stod(std::string(r[1])) / 1e6;
    mysqlpp::Query a = db->query("SELECT db_user, COUNT(*) FROM sa WHERE sentinel = 0 AND db_user IN " + in_list(bots) + " GROUP BY db_user");
    for (const mysqlpp::Row& r : a.store()) answered[std::string(r[0])] = std::stoll(std::string(r[1]));
    traffic.stop();
  }
  std::cout << "[ info ] after 3 s of saturation, per robot (id order): answers so far / oldest waiting request\n";
  double max_age = 0, min_age = 1e9;
  for (const Bot& b : bots) {
    const double age = oldest_s.count(b.name) ? oldest_s[b.name] : 0;
    max_age = std::max(max_age, age);
    min_age = std::min(min_age, age);
    std::cout << "[ info ]   " << b.name << " (id " << b.id << "): " << answered[b.name] << " / " << age << " s\n";
    EXPECT_GT(answered[b.name], 10) << b.name << " was starved while the others were served";
  }
  EXPECT_LT(max_age - min_age, 1.0) << "some robots wait much longer than others";
  EXPECT_TRUE(wait_until([&] { return waiting_requests(bots) == 0; }, seconds(30)));
  server.reset();
  expect_all_answered_once(bots);
}

// ---------------------------------------------------------------------------------------
// b. SIGKILL at random moments while robots keep sending.

TEST(ServerCrash, KilledAgainAndAgainLosesNothingAndAnswersNothingTwice) {
  constexpr int kRobots = 10;
  constexpr int kKills = 20;
  std::vector<Bot> bots = make_bots("crash_r", kRobots, true);
  fresh_log("crash_server.log");
  std::mt19937 rng(20240611);
  std::uniform_int_distribution<int> delay_ms(20, 300);

  const auto t0 = Clock::now();
  // A batch commits within a millisecond or two; the delay widens the window a kill must hit
  // to interrupt a transaction in flight (what this test is about), nothing else changes.
  const std::string flags = "--workers 2 --commit-delay-ms 5";
  auto server = std::make_unique<ServerProcess>(flags, "crash_server.log");
  TrafficGenerator traffic(bots, milliseconds(4));
  long long max_backlog = 0;
  // A kill lands on a serving server: the random delay counts from a worker's connect.
  // Under the sanitizers a start takes longer than the delay, and no kill hit a batch.
  auto connects = [&] {
    const std::string log = server->log();
    size_t n = 0;
    for (size_t at = log.find("connected as"); at != std::string::npos; at = log.find("connected as", at + 1)) ++n;
    return n;
  };
  size_t before = 0;  // connects logged before the running server started
  for (int k = 0; k < kKills; ++k) {
    wait_until([&] { return connects() > before; }, seconds(20), milliseconds(10));
    std::this_thread::sleep_for(milliseconds(delay_ms(rng)));
    server->kill9();
    max_backlog = std::max(max_backlog, waiting_requests(bots));
    before = connects();
    server = std::make_unique<ServerProcess>(flags, "crash_server.log");
  }
  // A little more traffic with a live server, then the robots stop and the server drains rr.
  std::this_thread::sleep_for(milliseconds(300));
  traffic.stop();
  const double kill_phase_s = elapsed_s(t0);
  const bool drained = wait_until([&] { return waiting_requests(bots) == 0; }, seconds(30), milliseconds(50));
  const double total_s = elapsed_s(t0);
  server.reset();
  const std::string log = read_file(temp_path("crash_server.log"));
  EXPECT_TRUE(drained) << waiting_requests(bots) << " requests never answered";

  // Some kills came before the process got far enough to log (a kill 20 ms after fork);
  // the kills that matter hit a transaction in flight: a GetPosEnd the log shows handled
  // twice was handled by a server killed before its commit, then again by the next one.
  size_t starts = 0;
  for (size_t p = log.find("fleetmap-server starting"); p != std::string::npos; p = log.find("fleetmap-server starting", p + 1))
    ++starts;
  static const std::regex re(R"(request (\d+) \(GetPosEnd\): no_goal)");
  std::map<unsigned long long, int> handled;
  for (auto it = std::sregex_iterator(log.begin(), log.end(), re); it != std::sregex_iterator(); ++it)
    ++handled[std::stoull((*it)[1])];
  size_t redone = 0;
  for (const auto& [id, n] : handled) redone += n > 1;
  EXPECT_GT(redone, 0u) << "no kill interrupted a transaction: the test proves little";
  expect_all_answered_once(bots);
  std::cout << "[ info ] " << traffic.sent() << " requests, " << kKills << " SIGKILLs in " << kill_phase_s << " s ("
            << starts << " processes got to log their start), largest backlog at a kill " << max_backlog
            << ", drained after " << total_s << " s; " << redone
            << " GetPosEnd handled in a transaction a kill undid, then again\n";
  if (HasFailure()) std::cerr << "server log (tail):\n" << log.substr(log.size() > 8000 ? log.size() - 8000 : 0);
}

// ---------------------------------------------------------------------------------------
// c. A robot holding locks on its answers does not stall the others.

struct Hold {
  const char* name;
  const char* isolation;
  const char* statement;
};

void PrintTo(const Hold& h, std::ostream* os) { *os << h.name; }  // test names and CTest lines

class StallGuard : public ::testing::TestWithParam<Hold> {};

// Since sentinels (sql/10_schema.sql, sa.sentinel) A's hold locks only its own range of
// sa's ix_sa_mine: no other robot's answers wait on it (tests/integration/sa_lock_test.cpp),
// but the server's insert of A's next answer does, and with it the other requests of the
// server's batch. So A asks (from a second connection) while it holds.
TEST_P(StallGuard, BlockingRobotIsEndedAndOthersAreServed) {
  const Hold hold = GetParam();
  ensure_example_map(kMap);
  // Names unique to this run, A right before B in sa's index, and B with no answers yet.
  const std::string tag = "st" + std::to_string(getpid()) + std::string(hold.name).substr(0, 3);
  const std::string a_name = tag + "_a", b_name = tag + "_b";
  const RemoveRobotsAtEnd cleanup{{a_name, b_name}};
  const std::string a_pw = add_robot(a_name, kMap), b_pw = add_robot(b_name, kMap);
  const std::string log_name = "stall_" + std::string(hold.name) + ".log";
  fresh_log(log_name);
  auto server = std::make_unique<ServerProcess>("--workers 2", log_name);

  SqlRobot a(a_name, a_pw);
  a.send("Ready", R"({"magic": 1})");
  ASSERT_TRUE(wait_until([&] { return a.peek().size() == 2; }, seconds(10))) << "A got no Start + SetMap";
  // A keeps its two answers unread, then opens a transaction that locks them and the gap after.
  a.connection().query(std::string("SET SESSION TRANSACTION ISOLATION LEVEL ") + hold.isolation).execute();
  a.connection().query("START TRANSACTION").execute();
  {
    mysqlpp::Query q = a.connection().query(hold.statement);
    if (std::string(hold.statement).rfind("SELECT", 0) == 0) q.store();
    else q.execute();
  }
  // The hold is real: an insert of A's next answer waits on A; one of B's does not (the
  // administrator tries, briefly).
  auto probe = [](const std::string& name) {
    auto db = admin();
    db->query("SET SESSION innodb_lock_wait_timeout = 1").execute();
    db->query("START TRANSACTION").execute();
    mysqlpp::Query ins = db->query();
    ins << "INSERT INTO sa (robot_id, db_user, request_id, op, params) VALUES (0, " << mysqlpp::quote << name
        << ", NULL, 'Probe', '{}')";
    bool waited = false;
    try {
      ins.execute();
    } catch (const mysqlpp::BadQuery& e) {
      waited = e.errnum() == 1205;
    }
    db->query("ROLLBACK").execute();
    return waited;
  };
  ASSERT_TRUE(probe(a_name)) << "A's " << hold.statement << " does not block inserts into sa: the test proves nothing";
  EXPECT_FALSE(probe(b_name)) << "A's " << hold.statement << " blocks inserts of B's answers (SPEC 5.3)";

  // A asks from a second connection: the server's answer to it waits on A's hold.
  SqlRobot a2(a_name, a_pw);
  const auto a_gps = a2.send("SendGPS", R"({"lat": 41.4, "lon": 2.1})");
  // B registers and asks: answered within a few seconds although A never commits.
  SqlRobot b(b_name, b_pw);
  const auto t0 = Clock::now();
  const auto ready = b.send("Ready", R"({"magic": 2})");
  std::vector<SqlAnswer> got = b.receive(2, seconds(8));
  const double wait_s = elapsed_s(t0);
  ASSERT_EQ(got.size(), 2u) << "B was stalled by A for " << wait_s << " s";
  EXPECT_EQ(got[0].op, "Start");
  EXPECT_EQ(got[1].op, "SetMap");
  EXPECT_EQ(got[0].request_id, ready);
  EXPECT_LT(wait_s, 6.0);
  // Served promptly afterwards.
  const auto t1 = Clock::now();
  const auto gps = b.send("SendGPS", R"({"lat": 41.4, "lon": 2.1})");
  got = b.receive(1, seconds(5));
  ASSERT_EQ(got.size(), 1u);
  EXPECT_EQ(got[0].request_id, gps);
  EXPECT_EQ(got[0].op, "OpAck");
  EXPECT_LT(elapsed_s(t1), 2.0);

  // A's holding connection was ended, and the server says so.
  EXPECT_TRUE(wait_until([&] {
    try {
      a.connection().query("SELECT 1").store();
      return false;
    } catch (const mysqlpp::Exception&) {
      return true;
    }
  }, seconds(8))) << "A's connection is still alive";
  const std::string log = read_file_once_it_has(temp_path(log_name), "of robot " + a_name + ":");
  EXPECT_NE(log.find("of robot " + a_name + ":"), std::string::npos) << log.substr(0, 6000);
  EXPECT_EQ(log.find("of robot " + b_name + ":"), std::string::npos) << "B was ended too:\n" << log.substr(0, 6000);
  // A's transaction was rolled back: its unread answers are still there for its next
  // connection, and the answer to its SendGPS after them.
  ASSERT_TRUE(wait_until([&] { return scalar("SELECT COUNT(*) FROM sa WHERE sentinel = 0 AND db_user = '" + a_name + "'") == 3; }))
      << scalar("SELECT COUNT(*) FROM sa WHERE sentinel = 0 AND db_user = '" + a_name + "'");
  SqlRobot again(a_name, a_pw);
  got = again.peek();
  ASSERT_EQ(got.size(), 3u);
  EXPECT_EQ(got[2].request_id, a_gps);
  EXPECT_EQ(got[2].op, "OpAck");
  std::cout << "[ info ] " << hold.name << ": B answered after " << wait_s << " s\n";
}

INSTANTIATE_TEST_SUITE_P(
    Holds, StallGuard,
    ::testing::Values(Hold{"select_for_update", "REPEATABLE READ", "SELECT * FROM sa_mine FOR UPDATE"},
                      Hold{"delete", "REPEATABLE READ", "DELETE FROM sa_mine"},
                      Hold{"serializable_read", "SERIALIZABLE", "SELECT * FROM sa_mine"}),
    [](const ::testing::TestParamInfo<Hold>& info) { return std::string(info.param.name); });

// Only the robot that blocks is ended (SPEC 5.3: the server "finds the blocking connection
// ... and ends it"): robot C handles its answers the careful way, in a READ COMMITTED
// transaction that locks just the answer in hand (SELECT ... WHERE id = ? FOR UPDATE, then
// DELETE, then COMMIT). That blocks nobody, so C must keep its connection while the server
// deals with A.
TEST(ServerStall, OnlyTheBlockingRobotIsEnded) {
  ensure_example_map(kMap);
  const std::string tag = "st" + std::to_string(getpid()) + "by";
  const std::string a_name = tag + "_a", b_name = tag + "_b", c_name = tag + "_c";
  const RemoveRobotsAtEnd cleanup{{a_name, b_name, c_name}};
  const std::string a_pw = add_robot(a_name, kMap), b_pw = add_robot(b_name, kMap), c_pw = add_robot(c_name, kMap);
  fresh_log("stall_bystander.log");
  auto server = std::make_unique<ServerProcess>("--workers 2", "stall_bystander.log");

  SqlRobot a(a_name, a_pw), c(c_name, c_pw);
  a.send("Ready", R"({"magic": 1})");
  c.send("Ready", R"({"magic": 3})");
  ASSERT_TRUE(wait_until([&] { return a.peek().size() == 2 && c.peek().size() == 2; }, seconds(10)));
  const unsigned long long c_first = c.peek().front().id;

  // C: READ COMMITTED, one answer locked while "handling" it.
  c.connection().query("SET SESSION TRANSACTION ISOLATION LEVEL READ COMMITTED").execute();
  c.connection().query("START TRANSACTION").execute();
  ASSERT_EQ(c.connection().query("SELECT * FROM sa_mine WHERE id = " + std::to_string(c_first) + " FOR UPDATE").store().size(), 1u);
  // C blocks nobody: an insert at B's place in sa goes through at once.
  {
    auto db = admin();
    db->query("SET SESSION innodb_lock_wait_timeout = 1").execute();
    db->query("START TRANSACTION").execute();
    mysqlpp::Query ins = db->query();
    ins << "INSERT INTO sa (robot_id, db_user, request_id, op, params) VALUES (0, " << mysqlpp::quote << b_name
        << ", NULL, 'Probe', '{}')";
    EXPECT_NO_THROW(ins.execute()) << "C's transaction blocks inserts into sa";
    db->query("ROLLBACK").execute();
  }

  // A blocks the server's answers to itself (its range of sa, sentinel included) and asks
  // from a second connection; B must be served, A ended, C left alone.
  a.connection().query("SET SESSION TRANSACTION ISOLATION LEVEL REPEATABLE READ").execute();
  a.connection().query("START TRANSACTION").execute();
  a.connection().query("SELECT * FROM sa_mine FOR UPDATE").store();
  SqlRobot a2(a_name, a_pw);
  a2.send("SendGPS", R"({"lat": 41.4, "lon": 2.1})");
  SqlRobot b(b_name, b_pw);
  b.send("Ready", R"({"magic": 2})");
  EXPECT_EQ(b.receive(2, seconds(8)).size(), 2u);
  EXPECT_TRUE(wait_until([&] {
    try {
      a.connection().query("SELECT 1").store();
      return false;
    } catch (const mysqlpp::Exception&) {
      return true;
    }
  }, seconds(8))) << "A's connection is still alive";

  const std::string log = read_file_once_it_has(temp_path("stall_bystander.log"), "of robot " + a_name + ":");
  EXPECT_NE(log.find("of robot " + a_name + ":"), std::string::npos) << log.substr(0, 6000);
  EXPECT_EQ(log.find("of robot " + c_name + ":"), std::string::npos)
      << "the server ended C, whose transaction blocked nothing:\n" << log.substr(0, 6000);
  bool c_alive = true;
  try {
    c.connection().query("DELETE FROM sa_mine WHERE id = " + std::to_string(c_first)).execute();
    c.connection().query("COMMIT").execute();
  } catch (const mysqlpp::Exception& e) {
    c_alive = false;
    ADD_FAILURE() << "C lost its connection (and its work in hand): " << e.what();
  }
  if (c_alive) {
    EXPECT_EQ(c.peek().size(), 1u);
  }
}

// ---------------------------------------------------------------------------------------
// d. SIGTERM while requests flow.

TEST(ServerShutdown, SigtermWhileBusyExitsCleanlyAndHalfHandlesNothing) {
  constexpr int kRobots = 8;
  std::vector<Bot> bots = make_bots("shut_r", kRobots, true);
  fresh_log("shutdown_server.log");
  fresh_log("shutdown_server2.log");
  std::optional<int> status;
  double exit_s = 0;
  {
    Daemon server("--workers 2", "shutdown_server.log");
    TrafficGenerator traffic(bots, milliseconds(2));
    // Flowing: answers arrive.
    ASSERT_TRUE(wait_until([&] { return scalar("SELECT COUNT(*) FROM sa WHERE sentinel = 0 AND db_user IN " + in_list(bots)) > 500; },
                           seconds(20)));
    const auto t0 = Clock::now();
    status = server.signal_and_wait(SIGTERM, seconds(10));
    exit_s = elapsed_s(t0);
    std::this_thread::sleep_for(milliseconds(200));  // robots go on sending to a stopped server
    traffic.stop();
  }
  ASSERT_TRUE(status) << "the server did not exit within 10 s of SIGTERM";
  EXPECT_TRUE(WIFEXITED(*status)) << "status " << *status;
  EXPECT_EQ(WEXITSTATUS(*status), 0);
  EXPECT_LT(exit_s, 3.0);
  const std::string log = read_file(temp_path("shutdown_server.log"));
  EXPECT_NE(log.find("fleetmap-server stopped"), std::string::npos);

  // Nothing half-handled: each request is either answered (all its answers) and gone from
  // rr, or unanswered and still in rr; per robot the answered ones come first.
  size_t answered = 0, waiting = 0;
  {
    auto db = admin();
    for (const Bot& b : bots) {
      EXPECT_TRUE(b.error.empty()) << b.name << ": " << b.error;
      const std::set<unsigned long long> still = waiting_ids(*db, b);
      const std::vector<Ans> got = answers_in_sa(*db, b);
      for (const std::string& p : check_answers(b, got, false, still)) ADD_FAILURE() << p;
      waiting += still.size();
      answered += b.sent.size() - still.size();
    }
  }
  EXPECT_GT(waiting, 0u) << "no request was left for the next server: the test did not stop a busy server";

  // The next server answers the rest, exactly once.
  {
    Daemon next("--workers 2", "shutdown_server2.log");
    EXPECT_TRUE(wait_until([&] { return waiting_requests(bots) == 0; }, seconds(20)));
    std::optional<int> s2 = next.signal_and_wait(SIGTERM, seconds(10));
    ASSERT_TRUE(s2);
    EXPECT_TRUE(WIFEXITED(*s2) && WEXITSTATUS(*s2) == 0);
  }
  expect_all_answered_once(bots);
  std::cout << "[ info ] exit 0 after " << exit_s << " s; at the stop " << answered << " requests answered, " << waiting
            << " waiting\n";
  if (HasFailure()) std::cerr << "server log (tail):\n" << log.substr(log.size() > 8000 ? log.size() - 8000 : 0);
}

}  // namespace
}  // namespace fleetmap::test
