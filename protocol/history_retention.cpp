#include "protocol/history_retention.h"

#include <cmath>
#include <string>

namespace fleetmap {
namespace {

// One table: the rows of these robots before the cutoff, through the table's (robot_id, t)
// index, so that the delete reads only what it deletes, whatever order the ids are in.
size_t delete_older(mysqlpp::Connection& c, const char* table, const std::string& robot_ids, const std::string& cutoff,
                    size_t batch) {
  mysqlpp::Query d = c.query();
  d << "DELETE FROM " << table << " WHERE robot_id IN (" << robot_ids << ") AND t < " << mysqlpp::quote << cutoff
    << " LIMIT " << batch;
  return d.execute().rows();
}

}  // namespace

HistoryDeleted delete_history_before(mysqlpp::Connection& c, double keep_s, size_t batch) {
  // Beyond a millennium nothing is that old, and the cutoff in microseconds would overflow.
  if (!(keep_s > 0) || keep_s > 3e10 || batch == 0) return {};
  // One cutoff for both tables, in the database's clock (the rows' t are its times).
  mysqlpp::Query q = c.query();
  q << "SELECT SYSDATE(6) - INTERVAL " << static_cast<long long>(std::llround(keep_s * 1e6)) << " MICROSECOND";
  const std::string cutoff(q.store()[0][0]);
  std::string ids;
  for (const mysqlpp::Row& r : c.query("SELECT id FROM robots").store()) ids += (ids.empty() ? "" : ",") + std::string(r[0]);
  if (ids.empty()) return {};
  HistoryDeleted out;
  out.trajectory_rows = delete_older(c, "trajectories", ids, cutoff, batch);
  out.gps_fixes = delete_older(c, "gps_fixes", ids, cutoff, batch);
  return out;
}

}  // namespace fleetmap
