#pragma once
// The server's work loop (SPEC 5.3). Each pass claims robots with waiting requests
// (their robots rows, FOR UPDATE SKIP LOCKED, so several workers and several server
// processes share the load and never work on one robot at once), handles each robot's
// requests in id order, writes the answers, deletes the requests and commits: all in one
// transaction, so a crash at any point loses no request and answers none twice.
// A pass costs a fixed handful of round trips, not several per request: one read each of
// the queue head, the claim, the claimed robots' requests and open tasks, then every
// write and the COMMIT together (protocol/write_batch.h). A failure that a whole batch
// cannot contain sends it again request by request in savepoints ("careful" pass).
// What each request does is server/daemon/dispatch.h; one worker also does the
// periodic work of server/daemon/housekeeping.h between batches.
#include <atomic>
#include <chrono>
#include <memory>
#include <string>

#include <mysql++/mysql++.h>

#include "protocol/db_settings.h"
#include "protocol/request_queue.h"
#include "protocol/robot_store.h"
#include "protocol/write_batch.h"
#include "server/core/map_cache.h"
#include "server/core/planner_cache.h"
#include "server/core/topo_cache.h"
#include "server/core/server_config.h"
#include "server/daemon/handlers/handler.h"
#include "server/daemon/housekeeping.h"

namespace fleetmap {

class RequestLoop {
 public:
  RequestLoop(DbSettings db, const ServerConfig& config, MapCache& cache, PlannerCache& planners, TopoCache& graphs,
              const std::atomic<bool>& stop, int worker, bool housekeeping);
  void run();  // until stop is set; finishes the transaction in hand first

  // One pass over waiting requests; returns how many requests it handled (for tests and
  // the benchmark driver).
  size_t serve_batch();

 private:
  void connect_with_retry();
  size_t serve(bool careful);
  std::vector<std::string> my_share(const std::vector<std::string>& waiting, bool mine) const;
  RequestWrites handle(ServedRobot& served, const Request& req, RobotRecords& records, RobotMaps& maps,
                       bool careful);

  DbSettings db_;
  const ServerConfig& config_;
  MapCache& cache_;
  PlannerCache& planners_;
  TopoCache& graphs_;
  const std::atomic<bool>& stop_;
  int worker_;
  bool housekeeping_;
  bool multi_statements_ = true;  // a batch's writes and COMMIT in one round trip
  std::unique_ptr<mysqlpp::Connection> conn_;
  HousekeepingSchedule schedule_;
};

}  // namespace fleetmap
