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
  for (const mysqlpp::Row& r : q.store())
    out.push_back({sql::to_uint(r[0]), sql::to_string(r[1]), task_state_from_string(sql::to_string(r[4])),
                   sql::to_string(r[5]), sql::to_string(r[6]), sql::to_string(r[7]), sql::to_double(r[2]),
                   sql::to_double(r[3])});
  return out;
}

}  // namespace fleetmap
