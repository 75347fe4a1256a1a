#include "server/daemon/stall_guard.h"

#include <set>
#include <thread>

#include <mysql++/mysql++.h>
#include <spdlog/spdlog.h>

#include "protocol/connection.h"
#include "protocol/sql_util.h"
#include "server/daemon/database_outage.h"

namespace fleetmap {

void StallGuard::run() {
  std::unique_ptr<mysqlpp::Connection> conn;
  std::set<unsigned long long> seen_last;  // blocking robot threads seen at the previous look
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
      mysqlpp::Query q = conn->query();
      q << "SELECT DISTINCT b.trx_mysql_thread_id, pb.USER, b.trx_started"
           " FROM information_schema.INNODB_LOCK_WAITS w"
           " JOIN information_schema.INNODB_TRX r ON r.trx_id = w.requesting_trx_id"
           " JOIN information_schema.INNODB_TRX b ON b.trx_id = w.blocking_trx_id"
           " JOIN information_schema.PROCESSLIST pr ON pr.ID = r.trx_mysql_thread_id"
           " JOIN information_schema.PROCESSLIST pb ON pb.ID = b.trx_mysql_thread_id"
           " WHERE pr.USER = "
        << mysqlpp::quote << db_.user << " AND pb.USER IN (SELECT db_user FROM robots)";
      std::set<unsigned long long> now;
      for (const mysqlpp::Row& row : q.store()) {
        const unsigned long long thread = sql::to_uint(row[0]);
        now.insert(thread);
        if (!seen_last.count(thread)) continue;  // give a momentary lock its chance
        try {
          execute(*conn, "KILL CONNECTION " + std::to_string(thread));
          spdlog::warn("ended connection {} of robot {}: its transaction (open since {}) held locks that blocked "
                       "the server",
                       thread, sql::to_string(row[1]), sql::to_string(row[2]));
        } catch (const mysqlpp::BadQuery& e) {
          spdlog::warn("could not end connection {} of robot {}: {}", thread, sql::to_string(row[1]), e.what());
        }
      }
      seen_last = std::move(now);
    } catch (const mysqlpp::Exception& e) {
      spdlog::warn("stall guard: {}", e.what());
      conn.reset();
    }
  }
}

}  // namespace fleetmap
