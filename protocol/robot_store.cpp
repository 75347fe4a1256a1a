#include "protocol/robot_store.h"

#include "common/geometry/number_format.h"
#include "protocol/sql_util.h"
#include "protocol/task_lifecycle.h"

namespace fleetmap {
namespace {

constexpr const char* kRobotColumns =
    "id, db_user, map_id, state, magic, x, y, theta, v, ini_x, ini_y, ini_theta, removed_at IS NOT NULL, laser_height, radius, "
    "body_height, can_stairs, can_ramps";
constexpr const char* kTaskColumns =
    "id, robot_id, goal_x, goal_y, state, answer_id, abort_answer_id, abort_requested_at IS NOT NULL, reason";

std::string n(double v) { return format_number(v); }

TaskRow read_task(const mysqlpp::Row& r) {
  TaskRow t;
  t.id = sql::to_uint(r[0]);
  t.robot_id = static_cast<unsigned>(sql::to_uint(r[1]));
  t.goal_x = sql::to_double(r[2]);
  t.goal_y = sql::to_double(r[3]);
  t.state = task_state_from_string(sql::to_string(r[4]));
  if (!r[5].is_null()) t.answer_id = sql::to_uint(r[5]);
  if (!r[6].is_null()) t.abort_answer_id = sql::to_uint(r[6]);
  t.abort_requested = sql::to_int(r[7]) != 0;
  t.reason = sql::to_string(r[8]);
  return t;
}

}  // namespace

RobotRow RobotStore::read_robot(const mysqlpp::Row& r) {
  RobotRow b;
  b.id = static_cast<unsigned>(sql::to_uint(r[0]));
  b.db_user = sql::to_string(r[1]);
  if (!r[2].is_null()) b.map_id = static_cast<unsigned>(sql::to_uint(r[2]));
  b.state = robot_state_from_string(sql::to_string(r[3]));
  b.magic = sql::opt_int(r[4]);
  b.x = sql::opt_double(r[5]);
  b.y = sql::opt_double(r[6]);
  b.theta = sql::opt_double(r[7]);
  b.v = sql::opt_double(r[8]);
  b.ini_x = sql::opt_double(r[9]);
  b.ini_y = sql::opt_double(r[10]);
  b.ini_theta = sql::opt_double(r[11]);
  b.removed = sql::to_int(r[12]) != 0;
  b.laser_height = sql::opt_double(r[13]);
  b.radius = sql::opt_double(r[14]);
  b.body_height = sql::opt_double(r[15]);
  b.can_stairs = sql::to_int(r[16]) != 0;
  b.can_ramps = sql::to_int(r[17]) != 0;
  return b;
}

std::vector<RobotRow> RobotStore::claim(const std::vector<std::string>& accounts) {
  if (accounts.empty()) return {};
  mysqlpp::Query q = c_.query(claim_sql(accounts));
  return claimed(q.store(), accounts);
}

std::string RobotStore::claim_sql(const std::vector<std::string>& accounts) {
  // No ORDER BY/LIMIT: InnoDB would lock in key order and always prefer the same
  // accounts under load; the caller bounds the list and orders it by waiting time.
  mysqlpp::Query q = c_.query();
  q << "SELECT " << kRobotColumns << " FROM robots WHERE db_user IN (";
  for (size_t i = 0; i < accounts.size(); ++i) q << (i ? "," : "") << mysqlpp::quote << accounts[i];
  q << ") FOR UPDATE SKIP LOCKED";
  return q.str();
}

std::vector<RobotRow> RobotStore::claimed(const mysqlpp::StoreQueryResult& res, const std::vector<std::string>& accounts) {
  std::vector<RobotRow> rows;
  for (const mysqlpp::Row& r : res) rows.push_back(read_robot(r));
  std::vector<RobotRow> out;
  for (const std::string& account : accounts)
    for (RobotRow& r : rows)
      if (r.db_user == account) out.push_back(std::move(r));
  return out;
}

std::optional<RobotRow> RobotStore::claim(unsigned robot_id) {
  mysqlpp::Query q = c_.query();
  q << "SELECT " << kRobotColumns << " FROM robots WHERE id = " << robot_id << " FOR UPDATE SKIP LOCKED";
  mysqlpp::StoreQueryResult res = q.store();
  if (res.empty()) return std::nullopt;
  return read_robot(res[0]);
}

void RobotStore::start_session(unsigned id, long long magic) {
  mysqlpp::Query q = c_.query();
  q << "UPDATE robots SET magic = " << magic
    << ", session_at = SYSDATE(6), state = " << sql::quoted(RobotState::Ready) << " WHERE id = " << id;
  q.execute();
}

void RobotStore::set_state(unsigned id, RobotState state) {
  mysqlpp::Query q = c_.query();
  q << "UPDATE robots SET state = " << sql::quoted(state) << " WHERE id = " << id;
  q.execute();
}

void RobotStore::record_image(unsigned id, const SendImageParams& p, const std::string& data, const std::string& at) {
  mysqlpp::Query q = c_.query();
  q << "INSERT INTO images (robot_id, t, x, y, object_id, format, data) VALUES (" << id << ", " << mysqlpp::quote << at
    << ", " << n(p.x) << ", " << n(p.y) << ", " << (p.object_id ? std::to_string(*p.object_id) : "NULL") << ", "
    << mysqlpp::quote << p.format << ", " << mysqlpp::quote << data << ")";
  q.execute();
}

void RobotStore::record_object(unsigned id, std::optional<unsigned> map_id, const SetObjectParams& p,
                               const std::string& at) {
  mysqlpp::Query q = c_.query();
  q << "INSERT INTO observed_objects (robot_id, map_id, t, x, y, object, pos) VALUES (" << id << ", "
    << (map_id ? std::to_string(*map_id) : "NULL") << ", " << mysqlpp::quote << at << ", " << n(p.x) << ", " << n(p.y)
    << ", " << mysqlpp::quote << p.object << ", Point(" << n(p.x) << ", " << n(p.y) << "))";
  q.execute();
}

std::optional<TaskRow> RobotStore::open_task(unsigned robot_id) {
  mysqlpp::Query q = c_.query();
  q << "SELECT " << kTaskColumns << " FROM tasks WHERE robot_id = " << robot_id << " AND state IN "
    << sql::open_task_states()
    << " ORDER BY id DESC LIMIT 1";
  mysqlpp::StoreQueryResult res = q.store();
  if (res.empty()) return std::nullopt;
  return read_task(res[0]);
}

std::vector<TaskRow> RobotStore::open_tasks(const std::vector<unsigned>& robot_ids) {
  if (robot_ids.empty()) return {};
  mysqlpp::Query q = c_.query(open_tasks_sql(robot_ids));
  return open_tasks_of(q.store());
}

std::string RobotStore::open_tasks_sql(const std::vector<unsigned>& robot_ids) {
  mysqlpp::Query q = c_.query();
  q << "SELECT " << kTaskColumns << " FROM tasks WHERE state IN " << sql::open_task_states() << " AND robot_id IN (";
  for (size_t i = 0; i < robot_ids.size(); ++i) q << (i ? "," : "") << robot_ids[i];
  q << ") ORDER BY id DESC";
  return q.str();
}

std::vector<TaskRow> RobotStore::open_tasks_of(const mysqlpp::StoreQueryResult& res) {
  std::vector<TaskRow> out;
  for (const mysqlpp::Row& r : res) {
    TaskRow t = read_task(r);
    bool newer_seen = false;  // the newest open task per robot, as open_task()
    for (const TaskRow& o : out) newer_seen = newer_seen || o.robot_id == t.robot_id;
    if (!newer_seen) out.push_back(std::move(t));
  }
  return out;
}

std::optional<TaskRow> RobotStore::task_pushed_as(unsigned robot_id, unsigned long long answer_id) {
  mysqlpp::Query q = c_.query();
  q << "SELECT " << kTaskColumns << " FROM tasks WHERE robot_id = " << robot_id << " AND (answer_id = " << answer_id
    << " OR abort_answer_id = " << answer_id << ")";
  mysqlpp::StoreQueryResult res = q.store();
  if (res.empty()) return std::nullopt;
  return read_task(res[0]);
}

void RobotStore::set_task_state(unsigned long long task_id, TaskState state, const std::string& reason) {
  mysqlpp::Query q = c_.query();
  q << "UPDATE tasks SET state = " << sql::quoted(state);
  if (!reason.empty()) q << ", reason = " << mysqlpp::quote << reason.substr(0, 255);
  q << " WHERE id = " << task_id;
  q.execute();
}

void RobotStore::set_task_answer(unsigned long long task_id, unsigned long long answer_id) {
  mysqlpp::Query q = c_.query();
  q << "UPDATE tasks SET answer_id = " << answer_id << " WHERE id = " << task_id;
  q.execute();
}

void RobotStore::set_task_abort_answer(unsigned long long task_id, unsigned long long answer_id) {
  mysqlpp::Query q = c_.query();
  q << "UPDATE tasks SET abort_answer_id = " << answer_id << " WHERE id = " << task_id;
  q.execute();
}

std::vector<unsigned> RobotStore::robots_with_pushes(size_t limit, unsigned modulus, unsigned remainder) {
  mysqlpp::Query q = c_.query();
  q << "SELECT DISTINCT t.robot_id FROM tasks t JOIN robots r ON r.id = t.robot_id"
       " WHERE r.magic IS NOT NULL AND r.removed_at IS NULL AND r.state <> "
    << sql::quoted(RobotState::Lost) << " AND t.state IN " << sql::open_task_states()
    << " AND ((t.answer_id IS NULL) OR (t.abort_requested_at IS NOT NULL AND t.abort_answer_id IS NULL))"
    << sql::share_condition("r.id", modulus, remainder) << " LIMIT " << limit;
  std::vector<unsigned> out;
  for (const mysqlpp::Row& r : q.store()) out.push_back(static_cast<unsigned>(sql::to_uint(r[0])));
  return out;
}

std::vector<unsigned> RobotStore::silent_robots(double seconds, size_t limit, unsigned modulus, unsigned remainder) {
  mysqlpp::Query q = c_.query();
  q << "SELECT r.id FROM robots r WHERE r.magic IS NOT NULL AND r.removed_at IS NULL AND r.state <> "
    << sql::quoted(RobotState::Lost) << " AND r.last_seen < SYSDATE(6) - INTERVAL "
    << static_cast<long long>(seconds * 1e6) << " MICROSECOND"
    << " AND NOT EXISTS (SELECT 1 FROM rr WHERE rr.db_user = r.db_user)"
    << sql::share_condition("r.id", modulus, remainder) << " LIMIT " << limit;
  std::vector<unsigned> out;
  for (const mysqlpp::Row& r : q.store()) out.push_back(static_cast<unsigned>(sql::to_uint(r[0])));
  return out;
}

}  // namespace fleetmap
