#pragma once
// The server's work loop (SPEC 5.3). Each pass claims robots with waiting requests
// (their robots rows, FOR UPDATE SKIP LOCKED, so several workers and several server
// processes share the load and never work on one robot at once), handles each robot's
// requests in id order, writes the answers, deletes the requests and commits: all in one
// transaction, so a crash at any point loses no request and answers none twice.
// The housekeeping worker also pushes operators' goals and aborts, and marks silent
// robots lost.
#include <atomic>
#include <chrono>
#include <memory>
#include <string>

#include <mysql++/mysql++.h>

#include "protocol/db_settings.h"
#include "protocol/request_queue.h"
#include "protocol/robot_store.h"
#include "server/map_cache.h"
#include "server/planner_cache.h"
#include "server/server_config.h"

namespace fleetmap {

class RequestLoop {
 public:
  RequestLoop(DbSettings db, const ServerConfig& config, MapCache& cache, PlannerCache& planners,
              const std::atomic<bool>& stop, int worker, bool housekeeping);
  void run();  // until stop is set; finishes the transaction in hand first

  // One pass over waiting requests; returns how many requests it handled (for tests and
  // the benchmark driver).
  size_t serve_batch();
  size_t push_operations();
  size_t mark_lost_robots();
  size_t drop_orphan_requests();

 private:
  void connect_with_retry();
  void handle(RobotRow& robot, const Request& req, RequestQueue& queue, RobotStore& robots);

  DbSettings db_;
  const ServerConfig& config_;
  MapCache& cache_;
  PlannerCache& planners_;
  const std::atomic<bool>& stop_;
  int worker_;
  bool housekeeping_;
  std::unique_ptr<mysqlpp::Connection> conn_;
  std::chrono::steady_clock::time_point next_housekeeping_{};
};

}  // namespace fleetmap
