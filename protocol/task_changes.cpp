#include "protocol/task_changes.h"

#include "protocol/sql_util.h"

namespace fleetmap {

std::string database_now(mysqlpp::Connection& c) {
  mysqlpp::StoreQueryResult r = c.query("SELECT CAST(NOW(6) AS CHAR)").store();
  return r.empty() ? std::string() : sql::to_string(r[0][0]);
}

std::vector<TaskInfo> tasks_updated_since(mysqlpp::Connection& c, const std::string& since, long long lookback_us,
                                          size_t limit) {
  mysqlpp::Query q = c.query();
  q << "SELECT id, robot, goal_x, goal_y, state, COALESCE(reason, ''), created_at, updated_at FROM v_tasks"
    << " WHERE updated_at > TIMESTAMP(" << mysqlpp::quote << since << ") - INTERVAL " << lookback_us << " MICROSECOND"
    << " ORDER BY updated_at, id LIMIT " << limit;
  std::vector<TaskInfo> out;
  for (const mysqlpp::Row& r : q.store()) out.push_back(task_from_row(r));
  return out;
}

}  // namespace fleetmap
