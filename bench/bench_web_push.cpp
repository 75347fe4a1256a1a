// bench-web-push: how fast the operator sees the fleet (driven by scripts/bench-web.sh).
//
// N robots (own account and connection each, plain SQL as robots written by others
// speak it) send SendPos at --hz to a running fleetmap-server, which stores each pose in
// robots. P viewers watch the same fleet, in two phases of the same run:
//   web  P WebSocket pages of a running fleetmap-web (/api/ws, signed in as the operator);
//   cli  P `fleetmap robots --json --watch S` processes, the CLI polling the same view:
//        the baseline an operator has without the web tier.
// Every SendPos carries a pose no robot sent before (x grows by 1 mm per send), so a
// viewer's copy of a robot's x names the request it shows.
//
// Measured per phase:
//   * push latency: from the end of the robot's INSERT INTO rr (the request committed) to
//     the moment a viewer received a state with that x, over every viewer and pose;
//   * poses seen: the share of (viewer, pose) pairs that reached the viewer (a viewer that
//     gets two poses of one robot in one feed period sees the latest only, by design);
//   * CPU (utime+stime from /proc, % of one core) of the viewers' side (fleetmap-web, or
//     the P CLI processes), of fleetmap-server and of mariadbd over the window.
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <mutex>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <unordered_map>
#include <vector>

#include <boost/asio/connect.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/websocket.hpp>
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "protocol/connection.h"
#include "protocol/db_settings.h"

namespace {

namespace asio = boost::asio;
namespace beast = boost::beast;
namespace http = beast::http;
namespace websocket = beast::websocket;
using asio::ip::tcp;
using Clock = std::chrono::steady_clock;
using fleetmap::DbSettings;
using fleetmap::Role;

struct Options {
  std::string config, password_dir, web = "127.0.0.1:8080", fleetmap = "build/bin/fleetmap", phases = "web cli";
  int robots = 200, pages = 5, seconds = 20, web_pid = 0, server_pid = 0, db_pid = 0;
  double hz = 3, watch_s = 0.1;
};

double cpu_seconds(int pid) {
  if (pid <= 0) return 0;
  std::ifstream f("/proc/" + std::to_string(pid) + "/stat");
  std::string s((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  const size_t close = s.rfind(')');
  if (close == std::string::npos) return 0;
  std::istringstream in(s.substr(close + 2));
  std::string field;
  double utime = 0, stime = 0;
  for (int i = 3; in >> field; ++i) {
    if (i == 14) utime = std::stod(field);
    if (i == 15) {
      stime = std::stod(field);
      break;
    }
  }
  return (utime + stime) / static_cast<double>(sysconf(_SC_CLK_TCK));
}

// Which pose a robot sent when: x in mm -> when its INSERT returned.
class SendLog {
 public:
  explicit SendLog(int robots) : sent_(robots) {}
  void sent(int robot, long long key, Clock::time_point t, bool in_window) {
    std::lock_guard<std::mutex> l(m_);
    sent_[robot][key] = {t, in_window};
    if (in_window) ++in_window_;
  }
  // Latency in ms of a pose a viewer received, or < 0 when it is not one of the window's.
  double latency(int robot, long long key, Clock::time_point got) {
    std::lock_guard<std::mutex> l(m_);
    auto it = sent_[robot].find(key);
    if (it == sent_[robot].end() || !it->second.in_window) return -1;
    return std::chrono::duration<double, std::milli>(got - it->second.t).count();
  }
  long long in_window() {
    std::lock_guard<std::mutex> l(m_);
    return in_window_;
  }

 private:
  struct Sent {
    Clock::time_point t;
    bool in_window = false;
  };
  std::mutex m_;
  std::vector<std::unordered_map<long long, Sent>> sent_;
  long long in_window_ = 0;
};

// What one viewer saw: the first receipt of each (robot, pose).
class Viewer {
 public:
  void saw(SendLog& log, int robot, long long key, Clock::time_point got) {
    const long long id = static_cast<long long>(robot) << 40 | (key & ((1LL << 40) - 1));
    if (!seen_.insert(id).second) return;
    const double ms = log.latency(robot, key, got);
    if (ms >= 0) latencies_.push_back(ms);
  }
  const std::vector<double>& latencies() const { return latencies_; }

 private:
  std::set<long long> seen_;
  std::vector<double> latencies_;
};

int robot_index(const std::string& name) {  // "wp0042" -> 41
  if (name.size() < 3 || name.compare(0, 2, "wp") != 0) return -1;
  return std::atoi(name.c_str() + 2) - 1;
}

void take_states(const nlohmann::json& robots, SendLog& log, Viewer& v, int n, Clock::time_point got) {
  for (const auto& r : robots) {
    const std::string name = r.value("name", r.value("robot", std::string()));
    const int i = robot_index(name);
    if (i < 0 || i >= n || !r.contains("x") || !r["x"].is_number()) continue;
    v.saw(log, i, std::llround(r["x"].get<double>() * 1000), got);
  }
}

// The robots: Ready once, then SendPos at hz, x growing by 1 mm per send.
class Fleet {
 public:
  explicit Fleet(const Options& o) : o_(o) {}

  void connect_all() {
    const DbSettings base = fleetmap::load_settings(Role::Robot, o_.config);
    for (int i = 0; i < o_.robots; ++i) {
      DbSettings s = base;
      char name[16];
      std::snprintf(name, sizeof name, "wp%04d", i + 1);
      s.user = name;
      std::ifstream pw(o_.password_dir + "/" + name + ".pw");
      std::getline(pw, s.password);
      conns_.push_back(fleetmap::connect(s));
      mysqlpp::Query q = conns_.back()->query();
      q << "INSERT INTO rr (op, params) VALUES ('Ready', '{\"magic\":" << (i + 1) << "}')";
      q.execute();
    }
    std::this_thread::sleep_for(std::chrono::seconds(2));  // the Start answers
    drain();
  }

  void run(SendLog& log, Clock::time_point start, Clock::time_point end, Clock::time_point stop,
           std::atomic<bool>& ok) {
    const int threads = 4;
    std::vector<std::thread> ts;
    for (int t = 0; t < threads; ++t)
      ts.emplace_back([&, t] {
        const auto period = std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(1.0 / o_.hz));
        std::vector<Clock::time_point> next;
        std::vector<int> mine;
        for (int i = t; i < o_.robots; i += threads) {
          mine.push_back(i);
          next.push_back(Clock::now() + period * (i % 97) / 97);  // phases spread over a period
        }
        while (Clock::now() < stop && ok) {
          for (size_t k = 0; k < mine.size(); ++k) {
            if (Clock::now() < next[k]) continue;
            const int i = mine[k];
            const long long key = 10000 + seq_[i]++;  // x = 10 m + 1 mm per send
            char params[160];
            std::snprintf(params, sizeof params, R"({"x":%.3f,"y":%.3f,"theta":0.5,"v":0.3,"w":0.0})", key / 1000.0,
                          20.0 + (i % 50));
            try {
              mysqlpp::Query q = conns_[i]->query();
              q << "INSERT INTO rr (op, params) VALUES ('SendPos', " << mysqlpp::quote << params << ")";
              q.execute();
            } catch (const std::exception& e) {
              std::fprintf(stderr, "bench-web-push: robot %d: %s\n", i + 1, e.what());
              ok = false;
              return;
            }
            const auto now = Clock::now();
            log.sent(i, key, now, now >= start && now < end);
            next[k] += period;
          }
          std::this_thread::sleep_for(std::chrono::milliseconds(1));
        }
      });
    for (auto& t : ts) t.join();
  }

  void drain() {
    for (auto& c : conns_) c->query("DELETE FROM sa_mine").execute();
  }

 private:
  const Options& o_;
  std::vector<std::unique_ptr<mysqlpp::Connection>> conns_;
  std::vector<long long> seq_ = std::vector<long long>(o_.robots, 0);  // per robot; one thread each
};

std::pair<std::string, std::string> host_port(const std::string& hp) {
  const size_t c = hp.rfind(':');
  return {hp.substr(0, c), hp.substr(c + 1)};
}

// Signs in as the operator of the config file: the session cookie.
std::string login(const Options& o) {
  const DbSettings op = fleetmap::load_settings(Role::Operator, o.config);
  auto [host, port] = host_port(o.web);
  asio::io_context io;
  tcp::socket sock(io);
  asio::connect(sock, tcp::resolver(io).resolve(host, port));
  http::request<http::string_body> req{http::verb::post, "/api/login", 11};
  req.set(http::field::host, o.web);
  req.set(http::field::content_type, "application/json");
  req.body() = nlohmann::json{{"user", op.user}, {"password", op.password}}.dump();
  req.prepare_payload();
  http::write(sock, req);
  beast::flat_buffer buf;
  http::response<http::string_body> res;
  http::read(sock, buf, res);
  if (res.result() != http::status::ok) throw std::runtime_error("login refused: " + res.body());
  const std::string cookie(res[http::field::set_cookie]);
  return cookie.substr(0, cookie.find(';'));
}

struct PhaseResult {
  std::string name;
  std::vector<double> latencies;
  long long expected = 0;  // in-window poses × viewers
  double viewer_cpu = 0, server_cpu = 0, db_cpu = 0, seconds = 0;
};

double quantile(std::vector<double> v, double q) {
  if (v.empty()) return NAN;
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, static_cast<size_t>(q * (v.size() - 1) + 0.5))];
}

PhaseResult run_phase(const Options& o, const std::string& phase, Fleet& fleet) {
  SendLog log(o.robots);
  PhaseResult r;
  r.name = phase;
  std::atomic<bool> stop{false}, ok{true};
  std::vector<Viewer> viewers(o.pages);
  std::vector<std::thread> readers;
  std::vector<pid_t> cli_pids;
  asio::io_context io;
  std::vector<std::unique_ptr<websocket::stream<tcp::socket>>> pages;

  if (phase == "web") {
    const std::string cookie = login(o);
    auto [host, port] = host_port(o.web);
    for (int p = 0; p < o.pages; ++p) {
      auto ws = std::make_unique<websocket::stream<tcp::socket>>(io);
      asio::connect(ws->next_layer(), tcp::resolver(io).resolve(host, port));
      ws->set_option(websocket::stream_base::decorator([&](websocket::request_type& req) {
        req.set(http::field::cookie, cookie);
        req.set(http::field::origin, "http://" + o.web);
      }));
      ws->handshake(o.web, "/api/ws");
      pages.push_back(std::move(ws));
    }
    for (int p = 0; p < o.pages; ++p)
      readers.emplace_back([&, p] {
        beast::flat_buffer buf;
        try {
          while (!stop) {
            pages[p]->read(buf);
            const auto got = Clock::now();
            const auto j = nlohmann::json::parse(beast::buffers_to_string(buf.data()), nullptr, false);
            buf.consume(buf.size());
            if (j.is_object() && j.value("type", "") == "robots") take_states(j["robots"], log, viewers[p], o.robots, got);
          }
        } catch (const std::exception&) {  // closed at the end
        }
      });
  } else {
    for (int p = 0; p < o.pages; ++p) {
      int fd[2];
      if (pipe(fd) != 0) throw std::runtime_error("pipe failed");
      const pid_t pid = fork();
      if (pid == 0) {
        dup2(fd[1], 1);
        close(fd[0]);
        close(fd[1]);
        char watch[32];
        std::snprintf(watch, sizeof watch, "%g", o.watch_s);
        execl(o.fleetmap.c_str(), o.fleetmap.c_str(), "robots", "--json", "--watch", watch, "--config",
              o.config.c_str(), static_cast<char*>(nullptr));
        _exit(127);
      }
      close(fd[1]);
      cli_pids.push_back(pid);
      readers.emplace_back([&, p, rfd = fd[0]] {
        FILE* in = fdopen(rfd, "r");
        std::string line;
        char chunk[65536];
        while (in && std::fgets(chunk, sizeof chunk, in)) {
          line += chunk;
          if (line.empty() || line.back() != '\n') continue;
          const auto got = Clock::now();
          const auto j = nlohmann::json::parse(line, nullptr, false);
          line.clear();
          if (j.is_array()) take_states(j, log, viewers[p], o.robots, got);
        }
        if (in) std::fclose(in);
      });
    }
  }

  // Warm-up 3 s, the window, then 2 s for the last poses to arrive.
  const auto start = Clock::now() + std::chrono::seconds(3);
  const auto end = start + std::chrono::seconds(o.seconds);
  const auto until = end + std::chrono::seconds(2);
  std::thread cpu([&] {
    std::this_thread::sleep_until(start);
    double v0 = 0;
    for (pid_t p : cli_pids) v0 += cpu_seconds(p);
    v0 += cpu_seconds(o.web_pid) * (phase == "web");
    const double s0 = cpu_seconds(o.server_pid), d0 = cpu_seconds(o.db_pid);
    std::this_thread::sleep_until(end);
    double v1 = 0;
    for (pid_t p : cli_pids) v1 += cpu_seconds(p);
    v1 += cpu_seconds(o.web_pid) * (phase == "web");
    r.seconds = o.seconds;
    r.viewer_cpu = 100 * (v1 - v0) / o.seconds;
    r.server_cpu = 100 * (cpu_seconds(o.server_pid) - s0) / o.seconds;
    r.db_cpu = 100 * (cpu_seconds(o.db_pid) - d0) / o.seconds;
  });
  fleet.run(log, start, end, until, ok);
  cpu.join();
  stop = true;
  for (auto& ws : pages) {
    beast::error_code ec;
    ws->next_layer().shutdown(tcp::socket::shutdown_both, ec);
    ws->next_layer().close(ec);
  }
  for (pid_t p : cli_pids) kill(p, SIGTERM);
  for (auto& t : readers) t.join();
  for (pid_t p : cli_pids) waitpid(p, nullptr, 0);
  fleet.drain();
  if (!ok) throw std::runtime_error("a robot failed; see above");
  for (const Viewer& v : viewers) r.latencies.insert(r.latencies.end(), v.latencies().begin(), v.latencies().end());
  r.expected = log.in_window() * o.pages;
  return r;
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  CLI::App app{"bench-web-push: the operator's view of a moving fleet, WebSocket pages of fleetmap-web beside the CLI "
               "polling the same view (scripts/bench-web.sh runs it)"};
  app.add_option("--config", o.config, "the instance's fleetmap.conf (operator account, database)")->required();
  app.add_option("--password-dir", o.password_dir, "wp0001.pw ...: the robots' passwords")->required();
  app.add_option("--web", o.web, "fleetmap-web's HOST:PORT")->capture_default_str();
  app.add_option("--fleetmap", o.fleetmap, "the fleetmap CLI (the baseline)")->capture_default_str();
  app.add_option("--robots", o.robots, "robots wp0001...")->capture_default_str();
  app.add_option("--pages", o.pages, "viewers: WebSocket pages, then CLI processes")->capture_default_str();
  app.add_option("--seconds", o.seconds, "measurement window of each phase")->capture_default_str();
  app.add_option("--hz", o.hz, "SendPos rate per robot")->capture_default_str();
  app.add_option("--watch-s", o.watch_s, "the CLI's refresh period (robots --watch; 0.1 is its smallest)")
      ->capture_default_str();
  app.add_option("--phases", o.phases, "web, cli or both")->capture_default_str();
  app.add_option("--web-pid", o.web_pid, "fleetmap-web's pid (CPU)");
  app.add_option("--server-pid", o.server_pid, "fleetmap-server's pid (CPU)");
  app.add_option("--db-pid", o.db_pid, "mariadbd's pid (CPU)");
  CLI11_PARSE(app, argc, argv);

  try {
    Fleet fleet(o);
    fleet.connect_all();
    std::vector<PhaseResult> results;
    for (const std::string phase : {"web", "cli"}) {
      if (o.phases.find(phase) == std::string::npos) continue;
      std::fprintf(stderr, "bench-web-push: phase %s, %d robots at %g Hz, %d viewers, %d s ...\n", phase.c_str(),
                   o.robots, o.hz, o.pages, o.seconds);
      results.push_back(run_phase(o, phase, fleet));
    }
    std::printf("\n%d robots x SendPos at %g Hz (%g poses/s), %d viewers, %d s window each\n", o.robots, o.hz,
                o.robots * o.hz, o.pages, o.seconds);
    std::printf("%-34s %9s %9s %9s %8s %9s %9s %9s\n", "viewers", "p50 ms", "p99 ms", "max ms", "seen %", "view cpu%",
                "srv cpu%", "db cpu%");
    for (const PhaseResult& r : results) {
      char name[64];
      if (r.name == "web")
        std::snprintf(name, sizeof name, "fleetmap-web, %d WebSocket pages", o.pages);
      else
        std::snprintf(name, sizeof name, "%d x robots --json --watch %g", o.pages, o.watch_s);
      std::printf("%-34s %9.1f %9.1f %9.1f %8.1f %9.1f %9.1f %9.1f\n", name, quantile(r.latencies, 0.5),
                  quantile(r.latencies, 0.99), quantile(r.latencies, 1.0),
                  r.expected ? 100.0 * r.latencies.size() / r.expected : 0.0, r.viewer_cpu, r.server_cpu, r.db_cpu);
    }
    std::printf("latency: robot's INSERT INTO rr returned -> viewer received that pose; seen: (viewer, pose) pairs "
                "received / sent in the window x viewers; cpu: %% of one core over the window\n");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench-web-push: %s\n", e.what());
    return 1;
  }
  return 0;
}
