#include "protocol/robot_whereabouts.h"

#include "protocol/fleet_store.h"
#include "protocol/sql_util.h"

namespace fleetmap {

RobotWhereabouts robot_whereabouts(mysqlpp::Connection& c, const std::string& robot) {
  mysqlpp::Query q = c.query();
  q << "SELECT r.id, r.map_id, COALESCE(m.name, ''), r.x, r.y, r.ini_x, r.ini_y, r.radius, r.body_height,"
       " r.can_stairs, r.state, COALESCE(r.last_seen, '') FROM robots r"
       " LEFT JOIN maps m ON m.id = r.map_id WHERE r.db_user = "
    << mysqlpp::quote << robot << " AND r.removed_at IS NULL";
  const mysqlpp::StoreQueryResult res = q.store();
  if (res.empty()) throw RobotNotFound(robot);
  const mysqlpp::Row& r = res[0];
  RobotWhereabouts w;
  w.id = static_cast<unsigned>(sql::to_uint(r[0]));
  if (!r[1].is_null()) w.map_id = static_cast<unsigned>(sql::to_uint(r[1]));
  w.map = sql::to_string(r[2]);
  const auto x = sql::opt_double(r[3]), y = sql::opt_double(r[4]);
  if (x && y) w.last_pose = Point{*x, *y};
  const auto ix = sql::opt_double(r[5]), iy = sql::opt_double(r[6]);
  if (ix && iy) w.initial_pose = Point{*ix, *iy};
  w.radius = sql::opt_double(r[7]);
  w.body_height = sql::opt_double(r[8]);
  w.can_stairs = sql::to_int(r[9]) != 0;
  w.state = robot_state_from_string(sql::to_string(r[10]));
  w.last_seen = sql::to_string(r[11]);
  return w;
}

}  // namespace fleetmap
