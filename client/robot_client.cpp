#include "client/robot_client.h"

#include <algorithm>
#include <string_view>

#include <boost/asio/io_context.hpp>
#include <boost/asio/post.hpp>
#include <boost/asio/steady_timer.hpp>
#include <spdlog/spdlog.h>

#include "protocol/connection.h"
#include "protocol/map_codec.h"

namespace fleetmap {

struct RobotClient::AliveTimer {
  boost::asio::io_context io;
  boost::asio::steady_timer timer{io};
  std::thread thread;
  std::chrono::milliseconds period{1000};
};

namespace {

// SPEC 5.2: every request but Alive, SendPos and OpAck has an answer.
bool has_answer(RequestOp op) { return op != RequestOp::Alive && op != RequestOp::SendPos && op != RequestOp::OpAck; }

// An answer due this long is given up for polling purposes (the server may have refused
// it silently or been replaced); the schedule falls back to idle.
constexpr std::chrono::seconds kForgetDue{60};

std::chrono::steady_clock::duration from_ms(double ms) {
  return std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double, std::milli>(ms));
}

// A statement the database rolled back whole, to be sent again: a deadlock, or on a
// Galera cluster a certification conflict with a commit on another node (1213); a lock
// wait past kLockWaitS (1205: autocommit, so the statement was the whole transaction);
// a request's INSERT given an id another row holds (1062 on PRIMARY: the robot never
// names the id, so it is the node's auto-increment counter, seen behind just after a
// node rejoined the cluster; the next try takes the next value).
bool rolled_back(const mysqlpp::Exception& e) {
  const auto* bq = dynamic_cast<const mysqlpp::BadQuery*>(&e);
  if (!bq) return false;
  const unsigned n = bq->errnum();
  return n == 1213 || n == 1205 ||
         (n == 1062 && std::string_view(bq->what()).find("for key 'PRIMARY'") != std::string_view::npos);
}

// How long one robot statement may wait on a row lock before it is sent again. The
// server's batch holds a robot's row for milliseconds; a longer wait is a stall, and on
// a Galera cluster a stall of every node (docs/galera.md, "A robot's lock wait").
constexpr unsigned kLockWaitS = 2;

// The node is gone or will not serve: move to the next host. 2000..2999: the client lost
// the server; 1047: a Galera node that is not primary or not synced ("WSREP has not yet
// prepared node for application use"); 1180: a commit the node could not replicate
// ("Error while appending streaming replication fragment (... Not connected to Primary
// Component)", seen as a cut healed); 1927: the connection was killed (the stall guard).
// Whether a failed INSERT committed is then looked up, never assumed.
bool connection_error(const mysqlpp::Exception& e) {
  if (const auto* bq = dynamic_cast<const mysqlpp::BadQuery*>(&e)) {
    const unsigned n = bq->errnum();
    return (n >= 2000 && n < 3000) || n == 1047 || n == 1180 || n == 1927 ||
           std::string_view(bq->what()).find("Primary Component") != std::string_view::npos;
  }
  return dynamic_cast<const mysqlpp::ConnectionFailed*>(&e) != nullptr;
}

}  // namespace

RobotClient::RobotClient(DbSettings settings, std::chrono::seconds reconnect_for, WaitPolicy wait)
    : settings_(std::move(settings)), reconnect_for_(reconnect_for), wait_(wait) {
  hosts_ = endpoints(settings_);
  open_connection();
  // Requests of an earlier session of this account are not this one's in doubt.
  last_request_ = found_at_connect_.value_or(0);
}

std::string RobotClient::node() const {
  const DbEndpoint& e = hosts_[host_ % hosts_.size()];
  return e.host + ":" + std::to_string(e.port);
}

void RobotClient::open_connection() {
  std::string failures;
  for (size_t tried = 0; tried < hosts_.size(); ++tried) {
    const size_t i = (host_ + tried) % hosts_.size();
    DbSettings s = settings_;
    if (!settings_.hosts.empty()) {
      s.host = hosts_[i].host;
      s.port = hosts_[i].port;
      s.socket.clear();
    }
    try {
      auto c = connect(s);
      RobotChannel ch(*c);
      // Back on the node of the connection that broke: a statement of it may still be
      // committing there (a connection the stall guard ended, say); wait until it is gone,
      // so that what we see below is final.
      if (i == host_ && connection_id_ != 0) {
        const auto until = Clock::now() + reconnect_for_;
        while (ch.session_alive(connection_id_) && Clock::now() < until)
          std::this_thread::sleep_for(std::chrono::milliseconds(20));
      }
      // On another node (the old one down: what it did not replicate did not commit):
      // wait until this one applied what the cluster committed (our requests, their
      // answers), then see what of ours is there above the last request known.
      ch.causal_reads(true);
      try {
        found_at_connect_ = ch.request_after(last_request_);
      } catch (const mysqlpp::BadQuery& e) {
        // 1146/1142: a database of before rr_mine. Working on: a request in doubt is then
        // sent again (at-least-once, as before).
        if (e.errnum() != 1146 && e.errnum() != 1142) throw;
        found_at_connect_.reset();
        spdlog::warn("robot client: {}; requests in doubt after a lost connection will be sent again", e.what());
      }
      ch.causal_reads(false);
      ch.limit_lock_waits(kLockWaitS);
      connection_id_ = ch.connection_id();
      conn_ = std::move(c);
      host_ = i;
      ++epoch_;
      return;
    } catch (const DbError& e) {
      failures += std::string(failures.empty() ? "" : "; ") + e.what();
    } catch (const mysqlpp::Exception& e) {
      failures += std::string(failures.empty() ? "" : "; ") + describe(s) + ": " + e.what();
    }
  }
  throw DbError(hosts_.size() > 1 ? "no database node answers: " + failures : failures);
}

void RobotClient::set_wait_policy(const WaitPolicy& w) {
  std::lock_guard lock(mutex_);
  wait_ = w;
}

RobotClient::Clock::time_point RobotClient::next_poll() const {
  if (due_.empty()) return last_poll_ + from_ms(wait_.idle_ms);
  Clock::time_point oldest = Clock::time_point::max();
  for (const auto& [id, at] : due_) oldest = std::min(oldest, at);
  const auto now = Clock::now();
  const double waited_ms = std::chrono::duration<double, std::milli>(now - oldest).count();
  return std::max(oldest + from_ms(wait_.first_poll_ms), last_poll_ + from_ms(wait_.answer_gap_ms(waited_ms)));
}

RobotClient::~RobotClient() { stop_alive(); }

template <typename F>
auto RobotClient::with_connection(F&& f) -> decltype(f(std::declval<RobotChannel&>())) {
  std::lock_guard lock(mutex_);
  const auto give_up = Clock::now() + reconnect_for_;
  double wait_s = 0.05;
  for (;;) {
    try {
      if (!conn_) {
        open_connection();
        ++reconnects_;
        spdlog::info("robot client: reconnected to {} as {}", node(), settings_.user);
      }
      RobotChannel ch(*conn_);
      return f(ch);
    } catch (const mysqlpp::Exception& e) {
      if (rolled_back(e) && Clock::now() <= give_up) {
        spdlog::debug("robot client: {}; sending it again", e.what());
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
        continue;
      }
      if (!connection_error(e) || Clock::now() > give_up) throw;
      spdlog::warn("robot client: connection to {} lost ({}); reconnecting", node(), e.what());
      conn_.reset();
      // The same node first (it refuses at once when it is down), then the next ones; a
      // node that will not serve (1047) fails its first read there and is passed over.
      continue;  // at once; the back-off is between rounds over all the hosts
    } catch (const DbError& e) {  // a round over every host failed: the database is still down
      if (Clock::now() > give_up) throw;
      spdlog::debug("robot client: {}; again in {:.2f} s", e.what(), wait_s);
      conn_.reset();
    }
    std::this_thread::sleep_for(std::chrono::duration<double>(wait_s));
    wait_s = std::min(wait_s * 2, 2.0);
  }
}

unsigned long long RobotClient::send(RequestOp op, const Json& params, const std::optional<std::string>& payload) {
  std::lock_guard lock(mutex_);
  const auto at = Clock::now();
  size_t sent_on = 0;  // the connection (epoch_) the INSERT went out on; 0: not yet
  const unsigned long long id = with_connection([&](RobotChannel& ch) -> unsigned long long {
    if (sent_on != 0 && sent_on != epoch_) {
      // The INSERT broke with its connection: committed or not? open_connection looked,
      // with causal reads, for a request of ours above the last one known.
      ++in_doubt_;
      if (found_at_connect_) {
        ++found_committed_;
        spdlog::info("robot client: request {} ({}) had committed; not sent again", *found_at_connect_, name(op));
        return *found_at_connect_;
      }
      spdlog::info("robot client: {} had not committed; sending it again", name(op));
    }
    sent_on = epoch_;
    return ch.send(op, params, payload, robot_id_);
  });
  last_request_ = std::max(last_request_, id);
  if (has_answer(op)) due_[id] = at;
  return id;
}

void RobotClient::fetch() {
  last_poll_ = Clock::now();
  ++polls_;
  std::erase_if(due_, [&](const auto& d) { return last_poll_ - d.second > kForgetDue; });
  // An answer counts as taken once it is handed over (inbox_); its delete is repeated
  // until it committed, also across a lost connection or a rollback (1213), so that none
  // is handed over twice and none stays in sa. What is left in sa_mine after those deletes
  // is new, whatever its id: on a Galera cluster, servers on two nodes number their
  // answers from each node's own counter (wsrep_auto_increment_control), and an answer
  // with a lower id can commit after one with a higher id was read.
  std::vector<unsigned long long> acks;
  with_connection([&](RobotChannel& ch) {
    while (!unremoved_.empty()) {
      ch.remove(unremoved_.back());
      unremoved_.pop_back();
    }
    for (ReceivedAnswer& a : ch.answers(1000)) {
      unremoved_.push_back(a.id);
      if (a.request_id) due_.erase(*a.request_id);
      const std::optional<AnswerOp> op = parse_answer_op(a.op);
      if (!a.request_id && (op == AnswerOp::SetPosEnd || op == AnswerOp::Abort)) acks.push_back(a.id);
      const unsigned long long id = a.id;
      inbox_.push_back(std::move(a));
      ch.remove(id);
      unremoved_.pop_back();
    }
    return 0;
  });
  // Pushed operations are acknowledged at once: the server records that we took them.
  for (unsigned long long id : acks) send(RequestOp::OpAck, Json{{"answer_id", id}});
}

std::vector<ReceivedAnswer> RobotClient::receive() {
  std::lock_guard lock(mutex_);
  if (Clock::now() >= next_poll()) fetch();
  std::vector<ReceivedAnswer> out(std::make_move_iterator(inbox_.begin()), std::make_move_iterator(inbox_.end()));
  inbox_.clear();
  return out;
}

std::vector<ReceivedAnswer> RobotClient::await(unsigned long long request_id, size_t n,
                                               std::chrono::milliseconds timeout) {
  const auto until = Clock::now() + timeout;
  std::vector<ReceivedAnswer> got;
  for (;;) {
    Clock::time_point poll_at;
    {
      std::lock_guard lock(mutex_);
      if (Clock::now() >= next_poll()) fetch();
      for (auto it = inbox_.begin(); it != inbox_.end() && got.size() < n;) {
        if (it->request_id == request_id) {
          got.push_back(std::move(*it));
          it = inbox_.erase(it);
        } else {
          ++it;
        }
      }
      // Still waiting for this request's answers (Ready has two): keep it due.
      if (got.size() < n && !due_.count(request_id)) due_[request_id] = last_poll_;
      poll_at = next_poll();
    }
    if (got.size() >= n) return got;
    if (Clock::now() > until)
      throw RobotClientError("no answer to request " + std::to_string(request_id) + " within " +
                             std::to_string(timeout.count()) + " ms (is fleetmap-server running?)");
    std::this_thread::sleep_until(std::min(poll_at, until + std::chrono::milliseconds(1)));
  }
}

RobotSession RobotClient::ready(long long magic, MapEncoding encoding, std::chrono::milliseconds timeout) {
  robot_id_.reset();  // the first Ready carries no robot id
  const auto id = send(RequestOp::Ready, Json{{"magic", magic}, {"encoding", std::string(name(encoding))}});
  std::vector<ReceivedAnswer> a = await(id, 1, timeout);
  if (a[0].op == "Error")
    throw RobotClientError("Ready refused: " + a[0].params.value("code", "?") + ": " + a[0].params.value("message", ""));
  if (a[0].op != "Start") throw RobotClientError("expected Start after Ready, got " + a[0].op);
  const StartParams start = decode_start(a[0].params);
  if (start.magic != magic) throw RobotClientError("Start carries another magic");
  std::vector<ReceivedAnswer> m = await(id, 1, timeout);
  if (m[0].op != "SetMap")
    throw RobotClientError("expected SetMap after Start, got " + m[0].op + " " + m[0].params.dump());
  RobotSession s;
  s.robot_id = start.robot_id;
  s.alive_period_s = start.alive_period_s;
  s.map_params = decode_set_map(m[0].params);
  s.map = decode_map(m[0].payload.value_or(""), s.map_params.encoding, MapKind::Window);
  robot_id_ = start.robot_id;
  return s;
}

void RobotClient::start_alive(std::chrono::milliseconds period) {
  stop_alive();
  alive_ = std::make_unique<AliveTimer>();
  alive_->period = period;
  auto* t = alive_.get();
  struct Tick {
    RobotClient* self;
    AliveTimer* t;
    void operator()(const boost::system::error_code& ec) const {
      if (ec) return;  // cancelled
      try {
        self->send(RequestOp::Alive);
      } catch (const std::exception& e) {
        spdlog::warn("robot client: Alive not sent: {}", e.what());
      }
      t->timer.expires_at(t->timer.expiry() + t->period);
      t->timer.async_wait(*this);
    }
  };
  t->timer.expires_after(period);
  t->timer.async_wait(Tick{this, t});
  t->thread = std::thread([t] { t->io.run(); });
}

void RobotClient::stop_alive() {
  if (!alive_) return;
  boost::asio::post(alive_->io, [t = alive_.get()] { t->timer.cancel(); });
  alive_->io.stop();
  if (alive_->thread.joinable()) alive_->thread.join();
  alive_.reset();
}

}  // namespace fleetmap
