#pragma once
// RobotClient: what a real robot links to speak RR/SA (SPEC 5) with its own account.
// Ready/Start handshake, every robot op, answers read from sa_mine in id order and
// deleted, pushed operations (SetPosEnd, Abort) acknowledged with OpAck, Alive on a
// Boost.Asio timer, and reconnection when the database goes away.
//
// Failover: DbSettings::hosts lists the database nodes (a Galera cluster); when the
// connection breaks, or the node stops serving (not primary, not synced), the client
// moves to the next host at once, then waits between rounds over all of them with a
// growing back-off (50 ms doubling to 2 s), for up to reconnect_for.
//
// Delivery (SPEC 5.3): a request whose INSERT broke with the connection is in doubt.
// After reconnecting the client looks for it (its own waiting requests in rr_mine, its
// answers in sa_mine, with causal reads on Galera) and sends it again only when it is in
// neither: a request with an answer is sent exactly once. One without (Alive, SendPos,
// OpAck) that committed and was served already leaves no trace, and is sent again
// (at-least-once; a repeated position or Alive is harmless). Answers are handed over
// exactly once: an answer counts as taken when it is handed over, and its delete is
// repeated after a lost connection until it committed.
//
// Waiting (protocol/wait_policy.h): sa_mine is polled on the WaitPolicy's schedule, by
// await() and by receive() alike: first_poll_ms after a request that has answers, then
// at gaps growing with the wait while one is due, every idle_ms otherwise. A receive()
// called sooner returns what the last poll brought, without a statement: a control loop
// may call it every cycle without loading the fleet's shared database.
#include <atomic>
#include <chrono>
#include <deque>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include <mysql++/mysql++.h>

#include "common/core/error.h"
#include "common/map/map.h"
#include "protocol/db_settings.h"
#include "protocol/params.h"
#include "protocol/robot_channel.h"
#include "protocol/wait_policy.h"

namespace fleetmap {

class RobotClientError : public Failure {
 public:
  using Failure::Failure;
};

struct RobotSession {
  unsigned robot_id = 0;
  double alive_period_s = 1;
  Map map;                  // the SetMap that followed Start
  SetMapParams map_params;
};

class RobotClient {
 public:
  using Clock = std::chrono::steady_clock;

  explicit RobotClient(DbSettings settings, std::chrono::seconds reconnect_for = std::chrono::seconds(60),
                       WaitPolicy wait = {});
  ~RobotClient();

  // Ready, then Start (same magic) and SetMap. Throws RobotClientError on Error or time-out.
  RobotSession ready(long long magic, MapEncoding encoding = MapEncoding::Seed,
                     std::chrono::milliseconds timeout = std::chrono::seconds(10));

  unsigned long long send(RequestOp op, const Json& params = Json::object(),
                          const std::optional<std::string>& payload = std::nullopt);

  // Answers that arrived since the last call, in id order; pushed SetPosEnd and Abort
  // are acknowledged (OpAck) before they are returned.
  std::vector<ReceivedAnswer> receive();

  // The n answers of one request (others stay queued for receive()). Throws on time-out.
  std::vector<ReceivedAnswer> await(unsigned long long request_id, size_t n,
                                    std::chrono::milliseconds timeout = std::chrono::seconds(10));

  // Sends Alive every period on a timer thread until stop_alive() or destruction.
  void start_alive(std::chrono::milliseconds period);
  void stop_alive();

  const WaitPolicy& wait_policy() const { return wait_; }
  void set_wait_policy(const WaitPolicy& w);
  size_t polls() const { return polls_; }  // SELECTs on sa_mine so far

  std::optional<unsigned> robot_id() const { return robot_id_; }
  size_t reconnects() const { return reconnects_; }
  // Requests whose INSERT broke with the connection, and of those, the ones found
  // committed after reconnecting (not sent again).
  size_t in_doubt() const { return in_doubt_; }
  size_t found_committed() const { return found_committed_; }
  // The node connected to now (or tried last), as "host:port".
  std::string node() const;

 private:
  template <typename F>
  auto with_connection(F&& f) -> decltype(f(std::declval<RobotChannel&>()));
  void fetch();  // sa_mine -> inbox_
  void open_connection();  // the current host, then the next ones: one round; throws DbError
  Clock::time_point next_poll() const;  // by the wait policy; under mutex_

  DbSettings settings_;
  std::chrono::seconds reconnect_for_;
  std::recursive_mutex mutex_;  // one connection, used by the caller and the Alive timer
  std::unique_ptr<mysqlpp::Connection> conn_;
  std::vector<DbEndpoint> hosts_;  // endpoints(settings_)
  std::atomic<size_t> host_{0};    // index into hosts_ of the node in use
  unsigned long long last_request_ = 0;  // the highest own request id known committed
  std::vector<unsigned long long> unremoved_;  // answers handed over, their delete not yet committed
  std::atomic<size_t> in_doubt_{0}, found_committed_{0};
  size_t epoch_ = 0;  // connections opened so far
  unsigned long long connection_id_ = 0;  // of the connection in use (or lost last), on hosts_[host_]
  std::optional<unsigned long long> found_at_connect_;  // request_after(last_request_) on connecting
  std::deque<ReceivedAnswer> inbox_;
  std::optional<unsigned> robot_id_;
  std::atomic<size_t> reconnects_{0};
  WaitPolicy wait_;
  std::map<unsigned long long, Clock::time_point> due_;  // requests sent whose answers are due -> sent at
  Clock::time_point last_poll_{};
  std::atomic<size_t> polls_{0};

  struct AliveTimer;
  std::unique_ptr<AliveTimer> alive_;
};

}  // namespace fleetmap
