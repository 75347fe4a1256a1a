#include "protocol/fleet_store.h"

#include <cmath>
#include <ctime>
#include <map>

#include "common/geometry/number_format.h"
#include "protocol/connection.h"
#include "protocol/sql_util.h"
#include "protocol/task_lifecycle.h"

namespace fleetmap {

namespace {

constexpr const char* kProfileColumns = "laser_height, radius, body_height, can_stairs, can_ramps";

RobotProfile read_profile(const mysqlpp::Row& r, size_t at) {
  RobotProfile p;
  p.laser_height = sql::opt_double(r[at]);
  p.radius = sql::opt_double(r[at + 1]);
  p.body_height = sql::opt_double(r[at + 2]);
  p.can_stairs = sql::to_int(r[at + 3]) != 0;
  p.can_ramps = sql::to_int(r[at + 4]) != 0;
  return p;
}

void check_range(const char* field, const std::optional<std::optional<double>>& v, double lo, bool lo_ok, double hi) {
  if (!v || !*v) return;
  const double d = **v;
  if (!std::isfinite(d) || d > hi || d < lo || (d == lo && !lo_ok))
    throw std::invalid_argument(std::string(field) + ": expected a number in " + (lo_ok ? "[" : "(") +
                                format_number(lo) + ", " + format_number(hi) + "] m, got " + format_number(d));
}

}  // namespace

void check_profile(const RobotProfileChange& c) {
  // The ranges of robots' ck_robots_profile (sql/10_schema.sql), without the zero radius
  // and body height that describe no robot.
  check_range("laser_height", c.laser_height, 0, true, 1000);
  check_range("radius", c.radius, 0, false, 100);
  check_range("body_height", c.body_height, 0, false, 1000);
}

void FleetStore::set_profile(const std::string& name, const RobotProfileChange& c) {
  check_profile(c);
  const unsigned id = robot_id(name);
  if (c.empty()) return;
  std::string set;
  auto add = [&](const char* column, const std::string& value) { set += (set.empty() ? "" : ", ") + std::string(column) + " = " + value; };
  auto num = [](const std::optional<double>& v) { return v ? format_number(*v) : std::string("NULL"); };
  if (c.laser_height) add("laser_height", num(*c.laser_height));
  if (c.radius) add("radius", num(*c.radius));
  if (c.body_height) add("body_height", num(*c.body_height));
  if (c.can_stairs) add("can_stairs", *c.can_stairs ? "TRUE" : "FALSE");
  if (c.can_ramps) add("can_ramps", *c.can_ramps ? "TRUE" : "FALSE");
  execute(c_, "UPDATE robots SET " + set + " WHERE id = " + std::to_string(id));
}

RobotProfile FleetStore::profile(const std::string& name) {
  mysqlpp::Query q = c_.query();
  q << "SELECT " << kProfileColumns << " FROM robots WHERE db_user = " << mysqlpp::quote << name
    << " AND removed_at IS NULL";
  mysqlpp::StoreQueryResult r = q.store();
  if (r.empty()) throw RobotNotFound(name);
  return read_profile(r[0], 0);
}

std::map<std::string, RobotProfile> FleetStore::profiles() {
  mysqlpp::Query q = c_.query(std::string("SELECT db_user, ") + kProfileColumns + " FROM robots WHERE removed_at IS NULL");
  std::map<std::string, RobotProfile> out;
  for (const mysqlpp::Row& r : q.store()) out.emplace(sql::to_string(r[0]), read_profile(r, 1));
  return out;
}

unsigned FleetStore::add_robot(const std::string& name, const std::string& password, const std::string& map,
                               int max_connections) {
  mysqlpp::Query q = c_.query();
  q << "CALL robot_add(" << mysqlpp::quote << name << ", " << mysqlpp::quote << password << ", " << mysqlpp::quote
    << map << ", " << max_connections << ")";
  try {
    q.execute();
  } catch (const mysqlpp::BadQuery& e) {
    if (e.errnum() == 1644) throw std::invalid_argument(e.what());  // SIGNAL from the procedure: its reason
    throw;
  }
  return robot_id(name);
}

void FleetStore::remove_robot(const std::string& name) {
  mysqlpp::Query q = c_.query();
  q << "CALL robot_remove(" << mysqlpp::quote << name << ")";
  try {
    q.execute();
  } catch (const mysqlpp::BadQuery& e) {
    if (e.errnum() == 1644) throw RobotNotFound(name);
    throw;
  }
}

unsigned FleetStore::robot_id(const std::string& name) {
  mysqlpp::Query q = c_.query();
  q << "SELECT id FROM robots WHERE db_user = " << mysqlpp::quote << name << " AND removed_at IS NULL";
  mysqlpp::StoreQueryResult r = q.store();
  if (r.empty()) throw RobotNotFound(name);
  return static_cast<unsigned>(sql::to_uint(r[0][0]));
}

std::vector<RobotStatus> FleetStore::status() {
  mysqlpp::Query q = c_.query(
      "SELECT robot_id, name, COALESCE(map, ''), state, x, y, theta, v, COALESCE(last_seen, ''), task_id,"
      " COALESCE(task_state, ''), goal_x, goal_y FROM v_robot_status ORDER BY name");
  std::vector<RobotStatus> out;
  for (const mysqlpp::Row& r : q.store()) {
    RobotStatus s;
    s.id = static_cast<unsigned>(sql::to_uint(r[0]));
    s.name = sql::to_string(r[1]);
    s.map = sql::to_string(r[2]);
    s.state = robot_state_from_string(sql::to_string(r[3]));
    s.x = sql::opt_double(r[4]);
    s.y = sql::opt_double(r[5]);
    s.theta = sql::opt_double(r[6]);
    s.v = sql::opt_double(r[7]);
    s.last_seen = sql::to_string(r[8]);
    if (!r[9].is_null()) {
      s.task_id = sql::to_uint(r[9]);
      s.task_state = task_state_from_string(sql::to_string(r[10]));
    }
    s.goal_x = sql::opt_double(r[11]);
    s.goal_y = sql::opt_double(r[12]);
    out.push_back(std::move(s));
  }
  return out;
}

unsigned long long FleetStore::assign_goal(const std::string& robot, double x, double y) {
  Transaction tx(c_);
  const unsigned id = robot_id(robot);
  mysqlpp::Query q = c_.query();
  q << "INSERT INTO tasks (robot_id, goal_x, goal_y) VALUES (" << id << ", " << format_number(x) << ", "
    << format_number(y) << ")";
  const unsigned long long task = q.execute().insert_id();
  // The previous open task ends now: the new SetPosEnd replaces its goal on the robot (an
  // Abort pushed after it would stop the robot on its way to the new goal).
  q.reset();
  q << "SELECT id, state FROM tasks WHERE robot_id = " << id << " AND id <> " << task << " AND state IN "
    << sql::open_task_states() << " FOR UPDATE";
  for (const mysqlpp::Row& r : q.store()) {
    const TaskTransition t = task_transition(task_state_from_string(sql::to_string(r[1])), TaskEvent::Replaced);
    if (!t) continue;
    mysqlpp::Query u = c_.query();
    u << "UPDATE tasks SET state = " << sql::quoted(t.next())
      << ", reason = 'replaced by task " << task << "' WHERE id = " << sql::to_uint(r[0]);
    u.execute();
  }
  tx.commit();
  return task;
}

bool FleetStore::request_abort(const std::string& robot, const std::string& reason) {
  const unsigned id = robot_id(robot);
  mysqlpp::Query q = c_.query();
  q << "UPDATE tasks SET abort_requested_at = SYSDATE(6), reason = " << mysqlpp::quote << reason.substr(0, 255)
    << " WHERE robot_id = " << id << " AND state IN " << sql::open_task_states() << " AND abort_requested_at IS NULL";
  return q.execute().rows() > 0;
}

void FleetStore::set_initial_pose(const std::string& robot, double x, double y, std::optional<double> theta) {
  const unsigned id = robot_id(robot);
  mysqlpp::Query q = c_.query();
  q << "UPDATE robots SET ini_x = " << format_number(x) << ", ini_y = " << format_number(y)
    << ", ini_theta = " << (theta ? format_number(*theta) : "NULL") << " WHERE id = " << id;
  q.execute();
}

std::vector<TaskInfo> FleetStore::tasks(const std::optional<std::string>& robot, size_t limit) {
  mysqlpp::Query q = c_.query();
  q << "SELECT id, robot, goal_x, goal_y, state, COALESCE(reason, ''), created_at, updated_at FROM v_tasks";
  if (robot) q << " WHERE robot = " << mysqlpp::quote << *robot;
  q << " ORDER BY id DESC LIMIT " << limit;
  std::vector<TaskInfo> out;
  for (const mysqlpp::Row& r : q.store()) out.push_back(task_from_row(r));
  return out;
}

TaskInfo task_from_row(const mysqlpp::Row& r) {
  return {sql::to_uint(r[0]), sql::to_string(r[1]), task_state_from_string(sql::to_string(r[4])),
          sql::to_string(r[5]), sql::to_string(r[6]), sql::to_string(r[7]), sql::to_double(r[2]),
          sql::to_double(r[3])};
}

namespace {

// "1764635762.123456" (seconds since the epoch, as UNIX_TIMESTAMP gives them) ->
// "2026-12-02T00:36:02.123456Z".
std::string iso8601_utc(const std::string& unix_seconds) {
  const size_t dot = unix_seconds.find('.');
  const std::time_t secs = static_cast<std::time_t>(std::stoll(unix_seconds.substr(0, dot)));
  std::string frac = dot == std::string::npos ? "" : unix_seconds.substr(dot + 1);
  std::tm tm{};
  gmtime_r(&secs, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%S", &tm);
  return std::string(buf) + (frac.empty() ? "" : "." + frac) + "Z";
}

}  // namespace

std::vector<TrajectoryPoint> FleetStore::trajectory(const std::string& robot, const std::optional<std::string>& since) {
  const unsigned id = robot_id(robot);
  mysqlpp::Query q = c_.query();
  // UNIX_TIMESTAMP of a TIMESTAMP column is its stored UTC instant, not converted
  // through the session's zone (which a DST change would make ambiguous).
  q << "SELECT t, x, y, theta, v, UNIX_TIMESTAMP(t) FROM trajectories WHERE robot_id = " << id;
  if (since && !since->empty() && std::string("smhd").find(since->back()) != std::string::npos &&
      since->find_first_not_of("0123456789") == since->size() - 1) {
    static const std::map<char, long long> kSeconds{{'s', 1}, {'m', 60}, {'h', 3600}, {'d', 86400}};
    q << " AND t >= SYSDATE(6) - INTERVAL " << std::stoll(since->substr(0, since->size() - 1)) * kSeconds.at(since->back())
      << " SECOND";
  } else if (since) {
    q << " AND t >= " << mysqlpp::quote << *since;
  }
  q << " ORDER BY t, id";
  std::vector<TrajectoryPoint> out;
  for (const mysqlpp::Row& r : q.store())
    out.push_back({sql::to_string(r[0]), sql::to_double(r[1]), sql::to_double(r[2]), sql::to_double(r[3]),
                   sql::to_double(r[4]), iso8601_utc(sql::to_string(r[5]))});
  return out;
}

}  // namespace fleetmap
