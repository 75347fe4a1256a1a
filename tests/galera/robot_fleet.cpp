// galera_robot_fleet: robots on RobotClient (client/robot_client.h) sending numbered
// requests for the fault runs (scripts/chaos-cluster.sh, tests/galera/chaos_test.sh) and
// the failover test. Each robot registers (Ready), then sends bursts of GetPosEnd (one
// answer each: Error no_goal, the robot has no goal) and takes the answers with
// receive(), until the run's time is up; then waits for what is still due.
//
// It judges what a broken system would get wrong, per robot, from the answers' request ids:
//   lost        a request never answered (within --answer-timeout)
//   twice       a request answered more than once
//   order       an answer to a request that came after an answer to a later one
//   foreign     an answer to no request this robot sent
// and prints one line of figures, "key value" pairs, for the scripts:
//   robots R ready R gave_up 0 sent N answered N lost 0 twice 0 order 0 foreign 0 reconnects K
//   reconnected_robots M in_doubt D found_committed F throughput_rps X p50_ms Y p99_ms Z
// Exit 0 when every robot registered, none gave up (an exception out of RobotClient) and
// lost, twice, order and foreign are all 0; else 1.
//
//   galera_robot_fleet --accounts FILE --hosts LIST [--database NAME] [--seconds S]
//                      [--burst B] [--answer-timeout S] [--stop-file F] [--pause-ms MS] [--log-level L]
// --stop-file: sending also ends once F exists (a fault run of unknown length).
// FILE: one robot a line, "name password" (host order: robot i starts on host i mod n).
#include <algorithm>
#include <atomic>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <thread>

#include <CLI/CLI.hpp>
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

#include "client/robot_client.h"

namespace {

using namespace fleetmap;
using Clock = std::chrono::steady_clock;

struct Account {
  std::string name, password;
};

struct Tally {
  bool ready = false;
  size_t sent = 0, answered = 0, lost = 0, twice = 0, order = 0, foreign = 0;
  size_t reconnects = 0, in_doubt = 0, found_committed = 0;
  std::vector<double> latency_ms;
  std::string error;
};

std::atomic<bool> g_stopped{false};  // the stop file appeared

void run_robot(const DbSettings& base, const Account& acc, size_t first_host, size_t burst, double answer_timeout_s,
               double pause_ms, Clock::time_point end, Tally& t) {
  DbSettings s = base;
  s.user = acc.name;
  s.password = acc.password;
  // Robots spread over the nodes: robot i starts on host i mod n and fails over in order.
  if (!s.hosts.empty()) std::rotate(s.hosts.begin(), s.hosts.begin() + static_cast<long>(first_host % s.hosts.size()), s.hosts.end());
  try {
    RobotClient client(s, std::chrono::seconds(static_cast<int>(answer_timeout_s)));
    client.ready(1000 + static_cast<long long>(first_host), MapEncoding::Seed,
                 std::chrono::milliseconds(static_cast<int>(answer_timeout_s * 1000)));
    t.ready = true;
    std::map<unsigned long long, Clock::time_point> sent_at;  // request id -> when
    std::map<unsigned long long, size_t> answers;              // request id -> answers seen
    unsigned long long last_answered = 0;
    auto take = [&](const std::vector<ReceivedAnswer>& got) {
      const auto now = Clock::now();
      for (const ReceivedAnswer& a : got) {
        if (!a.request_id || !sent_at.count(*a.request_id)) {
          ++t.foreign;
          spdlog::error("{}: answer {} ({}) to no request of ours", acc.name, a.id, a.op);
          continue;
        }
        const unsigned long long r = *a.request_id;
        if (++answers[r] > 1) {
          ++t.twice;
          spdlog::error("{}: request {} answered again (answer {})", acc.name, r, a.id);
          continue;
        }
        if (r < last_answered) {
          ++t.order;
          spdlog::error("{}: request {} answered after request {}", acc.name, r, last_answered);
        }
        last_answered = std::max(last_answered, r);
        ++t.answered;
        t.latency_ms.push_back(std::chrono::duration<double, std::milli>(now - sent_at[r]).count());
      }
    };
    while (Clock::now() < end && !g_stopped) {
      std::vector<unsigned long long> due;
      for (size_t i = 0; i < burst; ++i) {
        const unsigned long long id = client.send(RequestOp::GetPosEnd);
        sent_at[id] = Clock::now();
        due.push_back(id);
        ++t.sent;
      }
      const auto until = Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(answer_timeout_s));
      auto open = [&] {
        return std::any_of(due.begin(), due.end(), [&](unsigned long long id) { return answers[id] == 0; });
      };
      while (open() && Clock::now() < until) {
        take(client.receive());
        if (open()) std::this_thread::sleep_for(std::chrono::milliseconds(1));
      }
      for (unsigned long long id : due)
        if (answers[id] == 0) {
          ++t.lost;
          spdlog::error("{}: request {} not answered within {} s", acc.name, id, answer_timeout_s);
        }
      if (pause_ms > 0) std::this_thread::sleep_for(std::chrono::duration<double, std::milli>(pause_ms));
    }
    // Late doubles show up here.
    const auto settle = Clock::now() + std::chrono::milliseconds(600);
    while (Clock::now() < settle) {
      take(client.receive());
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    t.reconnects = client.reconnects();
    t.in_doubt = client.in_doubt();
    t.found_committed = client.found_committed();
  } catch (const std::exception& e) {
    // A robot that gave up counts against the run (the client should have carried on).
    t.error = e.what();
    if (const auto* bq = dynamic_cast<const mysqlpp::BadQuery*>(&e)) t.error += " (error " + std::to_string(bq->errnum()) + ")";
    spdlog::error("{}: gave up: {}", acc.name, t.error);
  }
  t.lost += t.sent - t.answered - std::min(t.sent - t.answered, t.lost);  // what it sent and never got
}

double percentile(std::vector<double> v, double p) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  const size_t i = std::min(v.size() - 1, static_cast<size_t>(p * static_cast<double>(v.size() - 1) + 0.5));
  return v[i];
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"galera_robot_fleet: robots on RobotClient sending numbered requests; counts lost, doubled and "
               "reordered answers (tests/galera/)."};
  std::string accounts_file, hosts, database = "fleetmap", log_level = "warn";
  double seconds = 10, answer_timeout_s = 60;
  size_t burst = 3;
  std::string stop_file;
  double pause_ms = 0;
  app.add_option("--accounts", accounts_file, "robots, one a line: 'name password'")->required()->check(CLI::ExistingFile);
  app.add_option("--hosts", hosts, "database nodes 'host:port,...'")->required();
  app.add_option("--database", database, "database name")->capture_default_str();
  app.add_option("--seconds", seconds, "send for this long")->capture_default_str();
  app.add_option("--burst", burst, "requests sent before their answers are awaited")->capture_default_str()->check(CLI::Range(1, 100));
  app.add_option("--answer-timeout", answer_timeout_s, "a request unanswered this long is lost, s")->capture_default_str();
  app.add_option("--stop-file", stop_file, "sending ends once this file exists");
  app.add_option("--pause-ms", pause_ms, "each robot waits this long between bursts (0: a closed loop)")->capture_default_str();
  app.add_option("--log-level", log_level, "trace, debug, info, warn, error")->capture_default_str();
  CLI11_PARSE(app, argc, argv);
  // The log on stderr: stdout holds only the figures line the scripts parse.
  spdlog::set_default_logger(spdlog::stderr_color_mt("fleet"));
  spdlog::set_level(spdlog::level::from_str(log_level));
  spdlog::set_pattern("%H:%M:%S.%e %^%-5l%$ [fleet] %v");

  std::vector<Account> accounts;
  std::ifstream in(accounts_file);
  for (std::string line; std::getline(in, line);) {
    std::istringstream ls(line);
    Account a;
    if (ls >> a.name >> a.password) accounts.push_back(a);
  }
  if (accounts.empty()) {
    std::cerr << "galera_robot_fleet: no 'name password' line in " << accounts_file << "\n";
    return 2;
  }
  DbSettings base;
  base.database = database;
  try {
    base.hosts = parse_hosts(hosts, "--hosts");
  } catch (const std::exception& e) {
    std::cerr << "galera_robot_fleet: " << e.what() << "\n";
    return 2;
  }
  base.host = base.hosts.front().host;
  base.port = base.hosts.front().port ? base.hosts.front().port : 3306;

  std::vector<Tally> tallies(accounts.size());
  const auto t0 = Clock::now();
  const auto end = t0 + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds));
  std::vector<std::thread> threads;
  for (size_t i = 0; i < accounts.size(); ++i)
    threads.emplace_back(run_robot, std::cref(base), std::cref(accounts[i]), i, burst, answer_timeout_s, pause_ms, end,
                         std::ref(tallies[i]));
  std::thread watcher;
  std::atomic<bool> joined{false};
  if (!stop_file.empty())
    watcher = std::thread([&] {
      while (!joined && !g_stopped) {
        if (std::filesystem::exists(stop_file)) g_stopped = true;
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
      }
    });
  for (auto& th : threads) th.join();
  joined = true;
  if (watcher.joinable()) watcher.join();
  const double wall_s = std::chrono::duration<double>(Clock::now() - t0).count();

  Tally sum;
  size_t ready = 0, reconnected = 0, gave_up = 0;
  for (const Tally& t : tallies) {
    ready += t.ready;
    gave_up += !t.error.empty();
    reconnected += t.reconnects > 0;
    sum.sent += t.sent;
    sum.answered += t.answered;
    sum.lost += t.lost;
    sum.twice += t.twice;
    sum.order += t.order;
    sum.foreign += t.foreign;
    sum.reconnects += t.reconnects;
    sum.in_doubt += t.in_doubt;
    sum.found_committed += t.found_committed;
    sum.latency_ms.insert(sum.latency_ms.end(), t.latency_ms.begin(), t.latency_ms.end());
  }
  std::printf("robots %zu ready %zu gave_up %zu sent %zu answered %zu lost %zu twice %zu order %zu foreign %zu reconnects %zu "
              "reconnected_robots %zu in_doubt %zu found_committed %zu throughput_rps %.1f p50_ms %.1f p99_ms %.1f\n",
              accounts.size(), ready, gave_up, sum.sent, sum.answered, sum.lost, sum.twice, sum.order, sum.foreign,
              sum.reconnects, reconnected, sum.in_doubt, sum.found_committed,
              // per second of the sending window (of the whole run when a stop file ended it)
              static_cast<double>(sum.answered) / std::max(g_stopped ? wall_s : seconds, 1e-3),
              percentile(sum.latency_ms, 0.5),
              percentile(sum.latency_ms, 0.99));
  const bool ok = ready == accounts.size() && gave_up == 0 && sum.lost == 0 && sum.twice == 0 && sum.order == 0 && sum.foreign == 0;
  return ok ? 0 : 1;
}
