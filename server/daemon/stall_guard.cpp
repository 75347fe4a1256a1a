#include "server/daemon/stall_guard.h"

#include <set>
#include <thread>

#include <mysql++/mysql++.h>
#include <spdlog/spdlog.h>

#include "protocol/connection.h"
#include "protocol/sql_util.h"
#include "server/daemon/database_outage.h"

namespace fleetmap {
namespace {

using Clock = std::chrono::steady_clock;

// One look: every robot connection whose transaction another connection waits on, with
// who waits. The waiter is this server's account or a robot's; others (operators) are
// not robots' victims the guard answers for.
mysqlpp::StoreQueryResult blockers(mysqlpp::Connection& conn, const std::string& server_user) {
  mysqlpp::Query q = conn.query();
  q << "SELECT DISTINCT b.trx_mysql_thread_id, pb.USER, b.trx_started, pr.USER"
       " FROM information_schema.INNODB_LOCK_WAITS w"
       " JOIN information_schema.INNODB_TRX r ON r.trx_id = w.requesting_trx_id"
       " JOIN information_schema.INNODB_TRX b ON b.trx_id = w.blocking_trx_id"
       " JOIN information_schema.PROCESSLIST pr ON pr.ID = r.trx_mysql_thread_id"
       " JOIN information_schema.PROCESSLIST pb ON pb.ID = b.trx_mysql_thread_id"
       " WHERE pb.USER IN (SELECT db_user FROM robots)"
       " AND (pr.USER = "
    << mysqlpp::quote << server_user << " OR (pr.USER IN (SELECT db_user FROM robots) AND pr.USER <> pb.USER))";
  return q.store();
}

}  // namespace

void StallGuard::run() {
  std::unique_ptr<mysqlpp::Connection> conn;
  std::set<unsigned long long> seen_last;  // robot threads blocking the server at the previous look
  std::map<unsigned long long, Clock::time_point> blocking_robots_since;  // thread -> first look it blocked a robot
  RetryBackoff backoff;
  while (!stop_) {
    std::this_thread::sleep_for(period_);
    if (!conn) {
      try {
        conn = connect(db_);
        backoff.reset();
      } catch (const DbError& e) {
        // The workers' back-off, and the process's one line per step (database_outage.h).
        if (DatabaseOutage::shared().report(DatabaseOutage::Clock::now())) spdlog::warn("stall guard: {}", e.what());
        std::this_thread::sleep_for(std::chrono::duration<double>(backoff.next_wait_s()));
        continue;
      }
    }
    try {
      const Clock::time_point look = Clock::now();
      std::set<unsigned long long> blocks_server;
      std::map<unsigned long long, Clock::time_point> blocks_robot;
      std::set<unsigned long long> ended;
      auto end = [&](unsigned long long thread, const std::string& robot, const std::string& why) {
        if (!ended.insert(thread).second) return;
        try {
          execute(*conn, "KILL CONNECTION " + std::to_string(thread));
          spdlog::warn("ended connection {} of robot {}: {}", thread, robot, why);
        } catch (const mysqlpp::BadQuery& e) {
          spdlog::warn("could not end connection {} of robot {}: {}", thread, robot, e.what());
        }
      };
      for (const mysqlpp::Row& row : blockers(*conn, db_.user)) {
        const unsigned long long thread = sql::to_uint(row[0]);
        const std::string robot = sql::to_string(row[1]), since = sql::to_string(row[2]), waiter = sql::to_string(row[3]);
        if (waiter == db_.user) {
          blocks_server.insert(thread);
          if (!seen_last.count(thread)) continue;  // give a momentary lock its chance
          end(thread, robot, "its transaction (open since " + since + ") held locks that blocked the server");
        } else {
          // Measured from the guard's first look that saw it (the waits' own trx_wait_started
          // has whole seconds only): the bound holds to within one period.
          const auto it = blocking_robots_since.find(thread);
          const Clock::time_point first = it == blocking_robots_since.end() ? look : it->second;
          blocks_robot.emplace(thread, first);
          const std::chrono::duration<double, std::milli> blocked = look - first;
          if (blocked < robot_block_) continue;
          end(thread, robot,
              "its transaction (open since " + since + ") blocked robot " + waiter + " for " +
                  std::to_string(static_cast<long long>(blocked.count())) + " ms (robot_block_ms " +
                  std::to_string(static_cast<long long>(robot_block_.count())) + ")");
        }
      }
      seen_last = std::move(blocks_server);
      blocking_robots_since = std::move(blocks_robot);
    } catch (const mysqlpp::Exception& e) {
      spdlog::warn("stall guard: {}", e.what());
      conn.reset();
    }
  }
}

}  // namespace fleetmap
