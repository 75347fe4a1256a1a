#include "server/daemon/request_loop.h"

#include <algorithm>
#include <map>
#include <set>
#include <stdexcept>
#include <thread>

#include <spdlog/spdlog.h>

#include "protocol/connection.h"
#include "protocol/map_store.h"
#include "protocol/ops.h"
#include "protocol/scene_store.h"
#include "server/daemon/handlers/handler.h"

namespace fleetmap {
namespace {

constexpr unsigned kLockWaitTimeout = 1205;
constexpr unsigned kDeadlock = 1213;

// A handler failed in a way that only a savepoint can contain.
struct RedoCarefully : std::runtime_error {
  using std::runtime_error::runtime_error;
};

bool retryable(const mysqlpp::BadQuery& e) { return e.errnum() == kLockWaitTimeout || e.errnum() == kDeadlock; }

// Client-side errors: the connection is gone (server restart, KILL, network).
bool connection_lost(unsigned errnum) { return errnum >= 2000 && errnum < 3000; }

}  // namespace

RequestLoop::RequestLoop(DbSettings db, const ServerConfig& config, MapCache& cache, PlannerCache& planners,
                         const std::atomic<bool>& stop, int worker, bool housekeeping)
    : db_(std::move(db)),
      config_(config),
      cache_(cache),
      planners_(planners),
      stop_(stop),
      worker_(worker),
      housekeeping_(housekeeping) {}

void RequestLoop::connect_with_retry() {
  double wait_s = 0.1;
  while (!stop_) {
    try {
      conn_ = connect(db_, multi_statements_);
      // Wait on a lock only briefly: a robot holding sa locks must not stall everyone (SPEC 5.3).
      execute(*conn_, "SET SESSION innodb_lock_wait_timeout = " + std::to_string(config_.lock_wait_timeout_s));
      spdlog::info("worker {}: connected as {}", worker_, describe(db_));
      return;
    } catch (const std::exception& e) {
      spdlog::warn("worker {}: {}; retrying in {:.1f} s", worker_, e.what(), wait_s);
      std::this_thread::sleep_for(std::chrono::duration<double>(wait_s));
      wait_s = std::min(wait_s * 2, 5.0);
    }
  }
}

void RequestLoop::run() {
  connect_with_retry();
  // Idle back-off: poll again at once after work, then wait longer and longer, up to
  // poll_max_ms, while rr stays empty (SPEC 9: a tight loop burns a core).
  double idle_ms = 0;
  unsigned housekeeping_passes = 0;
  while (!stop_) {
    size_t done = 0;
    try {
      if (!conn_) connect_with_retry();
      if (!conn_) break;
      done = serve_batch();
      if (housekeeping_ && std::chrono::steady_clock::now() >= next_housekeeping_) {
        done += push_operations();
        mark_lost_robots();
        drop_orphan_requests();
        // Every 2 s: delete observations past their time (SetObject, issue 8); the maps
        // and views skip them from expires_at on already.
        if (housekeeping_passes++ % 20 == 0) SceneStore(*conn_).expire_observations();
        next_housekeeping_ = std::chrono::steady_clock::now() + std::chrono::milliseconds(100);
      }
    } catch (const mysqlpp::BadQuery& e) {
      if (connection_lost(e.errnum())) {
        spdlog::warn("worker {}: connection lost ({}); reconnecting", worker_, e.what());
        conn_.reset();
      } else if (retryable(e)) {
        // A lock wait timed out or a deadlock: the transaction was undone; go again (the
        // stall guard ends a robot that keeps blocking us).
        spdlog::warn("worker {}: {} (error {}); retrying", worker_, e.what(), e.errnum());
      } else {
        spdlog::error("worker {}: database error {}: {}", worker_, e.errnum(), e.what());
        std::this_thread::sleep_for(std::chrono::milliseconds(200));
      }
      continue;
    } catch (const mysqlpp::Exception& e) {
      spdlog::warn("worker {}: {}; reconnecting", worker_, e.what());
      conn_.reset();
      continue;
    } catch (const std::exception& e) {
      // A bug, not the robots' doing: the transaction is rolled back; keep serving the others.
      spdlog::error("worker {}: {}", worker_, e.what());
      std::this_thread::sleep_for(std::chrono::milliseconds(200));
      continue;
    }
    if (done > 0) {
      idle_ms = 0;
    } else {
      idle_ms = std::clamp(idle_ms * 2, 0.25, config_.poll_max_ms);
      std::this_thread::sleep_for(std::chrono::duration<double, std::milli>(idle_ms));
    }
  }
  spdlog::info("worker {}: stopped", worker_);
}

size_t RequestLoop::serve_batch() {
  try {
    return serve(false);
  } catch (const mysqlpp::BadQuery& e) {
    if (retryable(e) || connection_lost(e.errnum())) throw;
    // A write of the batch failed (the transaction is rolled back): go again at once,
    // one request at a time in savepoints, so that only the request at fault gets an Error.
    spdlog::warn("worker {}: batch failed (database error {}: {}); serving it again request by request", worker_,
                 e.errnum(), e.what());
  } catch (const RedoCarefully& e) {
    spdlog::warn("worker {}: batch failed ({}); serving it again request by request", worker_, e.what());
  }
  return serve(true);
}

std::vector<std::string> RequestLoop::my_share(const std::vector<std::string>& waiting, bool mine) const {
  // Workers of one process take interleaved shares of the queue head, so that they do
  // not all reach for the same robots; servers of other processes meet only through
  // SKIP LOCKED.
  const size_t workers = static_cast<size_t>(std::max(1, config_.workers));
  std::vector<std::string> out;
  for (size_t i = 0; i < waiting.size() && out.size() < config_.batch_robots; ++i)
    if ((i % workers == static_cast<size_t>(worker_) % workers) == mine) out.push_back(waiting[i]);
  return out;
}

size_t RequestLoop::serve(bool careful) {
  RequestQueue queue(*conn_);
  RobotStore robots(*conn_);
  const std::vector<std::string> waiting =
      queue.waiting_accounts(config_.batch_robots * static_cast<size_t>(std::max(1, config_.workers)));
  if (waiting.empty()) return 0;

  Transaction tx(*conn_);
  std::vector<RobotRow> claimed = robots.claim(my_share(waiting, true));
  if (claimed.empty()) claimed = robots.claim(my_share(waiting, false));  // help the others
  if (claimed.empty()) return 0;

  std::vector<std::string> accounts;
  std::vector<unsigned> ids;
  std::map<std::string, RobotSession> sessions;
  for (RobotRow& r : claimed) {
    accounts.push_back(r.db_user);
    ids.push_back(r.id);
    std::string key = r.db_user;
    sessions.emplace(std::move(key), RobotSession{std::move(r), std::nullopt});
  }
  for (TaskRow& t : robots.open_tasks(ids))
    for (auto& [user, s] : sessions)
      if (s.robot.id == t.robot_id) s.open_task = t;
  const std::vector<Request> reqs =
      queue.requests_of(accounts, config_.batch_requests, config_.batch_requests * accounts.size());

  WriteBatch batch(*conn_, multi_statements_);
  MapStore maps(*conn_);
  MapInfoCache infos;
  std::map<std::string, std::string> last_seen;
  for (const Request& req : reqs) {
    RobotSession& s = sessions.at(req.db_user);
    if (!s.robot.removed) handle(s, req, robots, maps, infos, batch, careful);
    batch.remove_request(req.id);
    last_seen[req.db_user] = req.created_at;  // requests come in id order
  }
  for (auto& [user, s] : sessions) {
    if (s.robot.removed || !last_seen.count(user)) continue;  // another server took its requests
    if (s.robot.state == "lost") s.robot.state = "ready";   // anything it sends brings it back
    batch.robot(s.robot, last_seen[user]);
  }
  if (config_.commit_delay_ms > 0)
    std::this_thread::sleep_for(std::chrono::duration<double, std::milli>(config_.commit_delay_ms));
  batch.flush(/*commit=*/true);
  tx.committed_by_batch();
  return reqs.size();
}

void RequestLoop::handle(RobotSession& session, const Request& req, RobotStore& robots, MapStore& maps,
                         MapInfoCache& infos, WriteBatch& batch, bool careful) {
  RobotRow& robot = session.robot;
  HandlerContext ctx{config_, robots, maps, cache_, planners_, infos, session, robot, req, {}, {}};
  const RobotSession before = session;  // an Error leaves the robot as it was
  // Careful: each request in a savepoint with its writes sent at once, so that a
  // database error in one handler undoes that request's work only.
  if (careful) execute(*conn_, "SAVEPOINT request");
  auto refuse = [&](ErrorCode code, const std::string& message) {
    if (careful) execute(*conn_, "ROLLBACK TO SAVEPOINT request");
    session = before;
    ctx.writes.clear();
    ctx.writes.answers.push_back(
        {robot.id, robot.db_user, req.id, AnswerOp::Error, encode(ErrorParams{req.id, code, message}), std::nullopt});
  };
  try {
    const std::optional<RequestOp> op = parse_request_op(req.op);
    if (!op) throw ProtocolError(ErrorCode::UnknownOp, "unknown op '" + req.op.substr(0, 16) + "'");
    if (req.robot_id && *req.robot_id != robot.id)
      throw ProtocolError(ErrorCode::NotYourRobot, "robot_id " + std::to_string(*req.robot_id) +
                                                       " is not this account's robot (" + std::to_string(robot.id) + ")");
    if (*op != RequestOp::Ready && !robot.registered())
      throw ProtocolError(ErrorCode::NotRegistered, "send Ready first");
    ctx.params = parse_params(req.params);
    handler_for(*op)(ctx);
    batch.add(std::move(ctx.writes));
    if (careful) batch.flush(/*commit=*/false);
    return;
  } catch (const ProtocolError& e) {
    refuse(e.code(), e.what());
    spdlog::debug("worker {}: {} request {} ({}): {} {}", worker_, robot.db_user, req.id, req.op.substr(0, 16),
                  name(e.code()), e.what());
  } catch (const mysqlpp::BadQuery& e) {
    // Fast mode: no savepoint to go back to; the batch goes again carefully (serve_batch).
    if (!careful || retryable(e) || connection_lost(e.errnum())) throw;
    spdlog::error("worker {}: {} request {} ({}): database error {}: {}", worker_, robot.db_user, req.id,
                  req.op.substr(0, 16), e.errnum(), e.what());
    refuse(ErrorCode::Internal, "the server could not store this request");
  } catch (const mysqlpp::Exception&) {
    throw;  // the connection is in doubt: reconnect (run)
  } catch (const std::exception& e) {
    // Fast mode: its direct writes, if any, cannot be undone alone.
    if (!careful) throw RedoCarefully(e.what());
    spdlog::error("worker {}: {} request {} ({}): {}", worker_, robot.db_user, req.id, req.op.substr(0, 16), e.what());
    refuse(ErrorCode::Internal, e.what());
  }
  batch.add(std::move(ctx.writes));
  if (careful) batch.flush(/*commit=*/false);
}

size_t RequestLoop::drop_orphan_requests() {
  // Requests from accounts that are no robot (inserted by hand by an administrator):
  // nobody can read an answer; drop them so they do not sit at the head of the queue.
  // Housekeeping, not every batch: the scan grows with the queue.
  mysqlpp::Query q = conn_->query("SELECT id FROM rr WHERE db_user NOT IN (SELECT db_user FROM robots) LIMIT 100");
  std::vector<unsigned long long> orphans;
  for (const mysqlpp::Row& r : q.store()) orphans.push_back(std::stoull(std::string(r[0])));
  if (orphans.empty()) return 0;
  spdlog::warn("dropping {} request(s) from accounts that are no robot", orphans.size());
  RequestQueue(*conn_).remove(orphans);
  return orphans.size();
}

size_t RequestLoop::push_operations() {
  RobotStore robots(*conn_);
  RequestQueue queue(*conn_);
  size_t pushed = 0;
  for (unsigned id : robots.robots_with_pushes(config_.batch_robots)) {
    Transaction tx(*conn_);
    std::optional<RobotRow> robot = robots.claim(id);
    if (!robot) continue;  // another worker or server holds it
    std::optional<TaskRow> task = robots.open_task(id);
    if (!task) continue;
    if (task->abort_requested && !task->abort_answer_id) {
      if (!task->answer_id) {
        robots.set_task_state(task->id, "aborted");  // the robot never heard of it
      } else {
        const auto sa_id = queue.insert({id, robot->db_user, std::nullopt, AnswerOp::Abort, encode_abort(task->reason), std::nullopt});
        robots.set_task_abort_answer(task->id, sa_id);
        spdlog::info("pushed Abort of task {} to {}", task->id, robot->db_user);
      }
      ++pushed;
    } else if (!task->answer_id) {
      const auto sa_id = queue.insert({id, robot->db_user, std::nullopt, AnswerOp::SetPosEnd,
                                       encode(SetPoseParams{task->goal_x, task->goal_y, std::nullopt}), std::nullopt});
      robots.set_task_answer(task->id, sa_id);
      spdlog::info("pushed SetPosEnd of task {} ({}, {}) to {}", task->id, task->goal_x, task->goal_y, robot->db_user);
      ++pushed;
    }
    tx.commit();
  }
  return pushed;
}

size_t RequestLoop::mark_lost_robots() {
  RobotStore robots(*conn_);
  size_t lost = 0;
  const double silent_s = config_.alive_period_s * config_.lost_after_periods;
  for (unsigned id : robots.silent_robots(silent_s, config_.batch_robots)) {
    Transaction tx(*conn_);
    std::optional<RobotRow> robot = robots.claim(id);
    if (!robot) continue;
    robots.set_state(id, "lost");
    while (auto task = robots.open_task(id)) robots.set_task_state(task->id, "failed", "robot lost");
    tx.commit();
    spdlog::warn("robot {} is lost (silent for more than {:.1f} s)", robot->db_user, silent_s);
    ++lost;
  }
  return lost;
}

}  // namespace fleetmap
