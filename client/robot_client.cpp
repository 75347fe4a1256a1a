#include "client/robot_client.h"

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

// A transaction the database rolled back whole, to be sent again: a deadlock, or on a
// Galera cluster a certification conflict with a commit on another node (docs/galera.md).
bool rolled_back(const mysqlpp::Exception& e) {
  const auto* bq = dynamic_cast<const mysqlpp::BadQuery*>(&e);
  return bq && bq->errnum() == 1213;
}

bool connection_error(const mysqlpp::Exception& e) {
  if (const auto* bq = dynamic_cast<const mysqlpp::BadQuery*>(&e)) return bq->errnum() >= 2000 && bq->errnum() < 3000;
  return dynamic_cast<const mysqlpp::ConnectionFailed*>(&e) != nullptr;
}

}  // namespace

RobotClient::RobotClient(DbSettings settings, std::chrono::seconds reconnect_for, WaitPolicy wait)
    : settings_(std::move(settings)), reconnect_for_(reconnect_for), wait_(wait) {
  conn_ = connect(settings_);
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
        conn_ = connect(settings_);
        ++reconnects_;
        spdlog::info("robot client: reconnected as {}", describe(settings_));
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
      spdlog::warn("robot client: connection lost ({}); retrying", e.what());
      conn_.reset();
    } catch (const DbError& e) {  // reconnect failed: the database is still down
      if (Clock::now() > give_up) throw;
      conn_.reset();
    }
    std::this_thread::sleep_for(std::chrono::duration<double>(wait_s));
    wait_s = std::min(wait_s * 2, 2.0);
  }
}

unsigned long long RobotClient::send(RequestOp op, const Json& params, const std::optional<std::string>& payload) {
  std::lock_guard lock(mutex_);
  const auto at = Clock::now();
  const unsigned long long id = with_connection([&](RobotChannel& ch) { return ch.send(op, params, payload, robot_id_); });
  if (has_answer(op)) due_[id] = at;
  return id;
}

void RobotClient::fetch() {
  last_poll_ = Clock::now();
  ++polls_;
  std::erase_if(due_, [&](const auto& d) { return last_poll_ - d.second > kForgetDue; });
  // An answer counts as taken once its delete has committed, so that a statement retried
  // (with_connection) reads again exactly the answers not yet taken.
  std::vector<unsigned long long> acks;
  with_connection([&](RobotChannel& ch) {
    for (ReceivedAnswer& a : ch.answers(last_answer_, 1000)) {
      ch.remove(a.id);
      last_answer_ = a.id;
      if (a.request_id) due_.erase(*a.request_id);
      const std::optional<AnswerOp> op = parse_answer_op(a.op);
      if (!a.request_id && (op == AnswerOp::SetPosEnd || op == AnswerOp::Abort)) acks.push_back(a.id);
      inbox_.push_back(std::move(a));
    }
    return 0;
  });
  // Pushed operations are acknowledged at once: the server records that we took them.
  for (unsigned long long id : acks)
    with_connection([&](RobotChannel& ch) { return ch.send(RequestOp::OpAck, Json{{"answer_id", id}}, std::nullopt, robot_id_); });
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
