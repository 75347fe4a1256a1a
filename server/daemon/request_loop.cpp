#include "server/daemon/request_loop.h"

#include <algorithm>
#include <map>
#include <optional>
#include <stdexcept>
#include <thread>

#include <spdlog/spdlog.h>

#include "protocol/connection.h"
#include "protocol/ops.h"
#include "server/daemon/database_outage.h"
#include "server/daemon/db_handler_stores.h"
#include "server/daemon/dispatch.h"

namespace fleetmap {
namespace {

// Every result of a multi-statement, in order (a statement without rows gives an empty one).
std::vector<mysqlpp::StoreQueryResult> store_all(mysqlpp::Connection& c, const std::string& sql) {
  mysqlpp::Query q = c.query(sql);
  std::vector<mysqlpp::StoreQueryResult> out;
  out.push_back(q.store());
  while (q.more_results()) out.push_back(q.store_next());
  return out;
}

// A transaction whose START TRANSACTION goes out with the claim (one round trip); rolled
// back on the way out unless the batch's multi-statement committed it.
class StartedWithClaim {
 public:
  explicit StartedWithClaim(mysqlpp::Connection& c) : c_(c) {}
  ~StartedWithClaim() {
    if (done_) return;
    try {
      execute(c_, "ROLLBACK");
    } catch (...) {  // the connection may be gone; the server rolls back on disconnect
    }
  }
  StartedWithClaim(const StartedWithClaim&) = delete;
  StartedWithClaim& operator=(const StartedWithClaim&) = delete;
  void committed_by_batch() { done_ = true; }

 private:
  mysqlpp::Connection& c_;
  bool done_ = false;
};

constexpr unsigned kLockWaitTimeout = 1205;
constexpr unsigned kDeadlock = 1213;

// A handler failed in a way that only a savepoint can contain.
struct RedoCarefully : std::runtime_error {
  using std::runtime_error::runtime_error;
};

bool retryable(const mysqlpp::BadQuery& e) { return e.errnum() == kLockWaitTimeout || e.errnum() == kDeadlock; }

// Client-side errors: the connection is gone (server restart, KILL, network).
bool connection_lost(unsigned errnum) { return errnum >= 2000 && errnum < 3000; }

// A batch's results into its WriteBatch; careful: each request's writes sent at once,
// inside its savepoint.
class WriteBatchSink : public BatchSink {
 public:
  WriteBatchSink(WriteBatch& batch, bool careful) : batch_(batch), careful_(careful) {}
  void served(const Request& request, RequestWrites&& writes) override {
    batch_.add(std::move(writes));
    batch_.remove_request(request.id);
    if (careful_) batch_.flush(/*commit=*/false);
  }
  void robot_seen(const RobotRow& robot, const std::string& last_seen) override { batch_.robot(robot, last_seen); }

 private:
  WriteBatch& batch_;
  bool careful_;
};

}  // namespace

RequestLoop::RequestLoop(DbSettings db, const ServerConfig& config, MapCache& cache, PlannerCache& planners, TopoCache& graphs,
                         const std::atomic<bool>& stop, int worker, bool housekeeping)
    : db_(std::move(db)),
      config_(config),
      cache_(cache),
      planners_(planners),
      graphs_(graphs),
      stop_(stop),
      worker_(worker),
      housekeeping_(housekeeping) {}

void RequestLoop::connect_with_retry() {
  RetryBackoff backoff;
  DatabaseOutage& outage = DatabaseOutage::shared();
  while (!stop_) {
    try {
      conn_ = connect(db_, multi_statements_);
      // Wait on a lock only briefly: a robot holding sa locks must not stall everyone (SPEC 5.3).
      execute(*conn_, "SET SESSION innodb_lock_wait_timeout = " + std::to_string(config_.lock_wait_timeout_s));
      if (outage.end()) spdlog::info("database reachable again");
      spdlog::info("worker {}: connected as {}", worker_, describe(db_));
      return;
    } catch (const std::exception& e) {
      const double wait_s = backoff.next_wait_s();
      // One line per back-off step for the process, not one per worker and attempt.
      if (outage.report(DatabaseOutage::Clock::now()))
        spdlog::warn("{}; retrying (every {:.1f} s at most)", e.what(), DatabaseOutage::kLastStepS);
      else
        spdlog::debug("worker {}: {}; retrying in {:.1f} s", worker_, e.what(), wait_s);
      std::this_thread::sleep_for(std::chrono::duration<double>(wait_s));
    }
  }
}

void RequestLoop::run() {
  connect_with_retry();
  // Idle back-off: poll again at once after work, then wait longer and longer, up to
  // poll_max_ms, while rr stays empty (SPEC 9: a tight loop burns a core).
  double idle_ms = 0;
  while (!stop_) {
    size_t done = 0;
    try {
      if (!conn_) connect_with_retry();
      if (!conn_) break;
      done = serve_batch();
      if (housekeeping_)
        if (const auto pass = schedule_.due(std::chrono::steady_clock::now()))
          done += Housekeeping(*conn_, config_).run(*pass);
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
      queue.waiting_accounts(config_.batch_robots * static_cast<size_t>(std::max(1, config_.workers)),
                             config_.partition.count, config_.partition.index);
  if (waiting.empty()) return 0;

  // Round trips of a pass (docs/benchmarks.md): the queue head above; START TRANSACTION
  // with the claim; the claimed robots' open tasks with their requests; the handlers' own
  // reads; every write with the COMMIT (write_batch.h). Without multi-statements, one each.
  std::optional<Transaction> tx;
  std::optional<StartedWithClaim> tx_multi;
  const std::vector<std::string> mine = my_share(waiting, true);
  std::vector<RobotRow> claimed;
  if (multi_statements_) {
    tx_multi.emplace(*conn_);  // before sending: a failed claim still rolls back
    if (mine.empty()) {
      execute(*conn_, "START TRANSACTION");
    } else {
      claimed = robots.claimed(store_all(*conn_, "START TRANSACTION;\n" + robots.claim_sql(mine)).back(), mine);
    }
  } else {
    tx.emplace(*conn_);
    claimed = robots.claim(mine);
  }
  if (claimed.empty()) claimed = robots.claim(my_share(waiting, false));  // help the others
  if (claimed.empty()) return 0;

  std::vector<std::string> accounts;
  std::vector<unsigned> ids;
  std::map<std::string, ServedRobot> served;
  for (RobotRow& r : claimed) {
    accounts.push_back(r.db_user);
    ids.push_back(r.id);
    std::string key = r.db_user;
    served.emplace(std::move(key), ServedRobot{std::move(r), std::nullopt});
  }
  std::vector<TaskRow> tasks;
  std::vector<Request> reqs;
  const size_t total = config_.batch_requests * accounts.size();
  if (multi_statements_) {
    const std::vector<mysqlpp::StoreQueryResult> res =
        store_all(*conn_, robots.open_tasks_sql(ids) + ";\n" + queue.requests_sql(accounts, total));
    tasks = RobotStore::open_tasks_of(res.at(0));
    reqs = RequestQueue::requests_from(res.at(1), config_.batch_requests);
  } else {
    tasks = robots.open_tasks(ids);
    reqs = queue.requests_of(accounts, config_.batch_requests, total);
  }
  for (TaskRow& t : tasks)
    for (auto& [user, s] : served)
      if (s.robot.id == t.robot_id) s.open_task = t;

  WriteBatch batch(*conn_, multi_statements_);
  WriteBatchSink sink(batch, careful);
  DbRobotRecords records(*conn_);
  DbRobotMaps maps(*conn_, cache_, planners_, graphs_);
  serve_requests(
      served, reqs, [&](ServedRobot& s, const Request& req) { return handle(s, req, records, maps, careful); }, sink);
  if (config_.commit_delay_ms > 0)
    std::this_thread::sleep_for(std::chrono::duration<double, std::milli>(config_.commit_delay_ms));
  batch.flush(/*commit=*/true);
  if (tx) tx->committed_by_batch();
  if (tx_multi) tx_multi->committed_by_batch();
  return reqs.size();
}

RequestWrites RequestLoop::handle(ServedRobot& served, const Request& req, RobotRecords& records, RobotMaps& maps,
                                  bool careful) {
  const ServedRobot before = served;
  // Careful: each request in a savepoint with its writes sent at once (WriteBatchSink),
  // so that a database error in one handler undoes that request's work only.
  if (careful) execute(*conn_, "SAVEPOINT request");
  auto refuse = [&](ErrorCode code, const std::string& message) {
    if (careful) execute(*conn_, "ROLLBACK TO SAVEPOINT request");
    served = before;
    return error_answer(served.robot, req, code, message);
  };
  const RobotRow& robot = before.robot;
  try {
    RequestWrites w = dispatch(config_, records, maps, served, req);
    // A refusal: the handler wrote nothing directly (handler.h); in a savepoint, make
    // sure of it.
    if (careful && w.refused) execute(*conn_, "ROLLBACK TO SAVEPOINT request");
    return w;
  } catch (const mysqlpp::BadQuery& e) {
    // Fast mode: no savepoint to go back to; the batch goes again carefully (serve_batch).
    if (!careful || retryable(e) || connection_lost(e.errnum())) throw;
    spdlog::error("worker {}: {} request {} ({}): database error {}: {}", worker_, robot.db_user, req.id,
                  req.op.substr(0, 16), e.errnum(), e.what());
    return refuse(ErrorCode::Internal, "the server could not store this request");
  } catch (const mysqlpp::Exception&) {
    throw;  // the connection is in doubt: reconnect (run)
  } catch (const std::exception& e) {
    // Fast mode: its direct writes, if any, cannot be undone alone.
    if (!careful) throw RedoCarefully(e.what());
    spdlog::error("worker {}: {} request {} ({}): {}", worker_, robot.db_user, req.id, req.op.substr(0, 16), e.what());
    return refuse(ErrorCode::Internal, e.what());
  }
}

}  // namespace fleetmap
