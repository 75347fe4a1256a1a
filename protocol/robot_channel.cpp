#include "protocol/robot_channel.h"

#include "protocol/sql_util.h"

namespace fleetmap {

unsigned long long RobotChannel::send(RequestOp op, const Json& params, const std::optional<std::string>& payload,
                                      std::optional<unsigned> robot_id) {
  mysqlpp::Query q = c_.query();
  q << "INSERT INTO rr (robot_id, op, params, payload) VALUES (" << (robot_id ? std::to_string(*robot_id) : "NULL")
    << ", " << mysqlpp::quote << std::string(name(op)) << ", " << mysqlpp::quote << params.dump() << ", ";
  if (payload) q << mysqlpp::quote << *payload;
  else q << "NULL";
  q << ")";
  return q.execute().insert_id();
}

std::vector<ReceivedAnswer> RobotChannel::answers(size_t limit) {
  mysqlpp::Query q = c_.query();
  q << "SELECT id, robot_id, request_id, op, params, payload FROM sa_mine ORDER BY id LIMIT " << limit;
  std::vector<ReceivedAnswer> out;
  for (const mysqlpp::Row& r : q.store()) {
    ReceivedAnswer a;
    a.id = sql::to_uint(r[0]);
    a.robot_id = static_cast<unsigned>(sql::to_uint(r[1]));
    if (!r[2].is_null()) a.request_id = sql::to_uint(r[2]);
    a.op = sql::to_string(r[3]);
    a.params = Json::parse(sql::to_string(r[4]), nullptr, false);
    if (!r[5].is_null()) a.payload = sql::to_string(r[5]);
    out.push_back(std::move(a));
  }
  return out;
}

void RobotChannel::remove(unsigned long long answer_id) {
  mysqlpp::Query q = c_.query();
  q << "DELETE FROM sa_mine WHERE id = " << answer_id;
  q.execute();
}

std::optional<unsigned long long> RobotChannel::request_after(unsigned long long after) {
  // rr_mine first: a request served between the two reads shows its answer in the second.
  mysqlpp::Query q = c_.query();
  q << "SELECT MAX(id) FROM rr_mine WHERE id > " << after;
  mysqlpp::StoreQueryResult w = q.store();
  if (!w.empty() && !w[0][0].is_null()) return sql::to_uint(w[0][0]);
  mysqlpp::Query a = c_.query();
  a << "SELECT MAX(request_id) FROM sa_mine WHERE request_id > " << after;
  mysqlpp::StoreQueryResult r = a.store();
  if (!r.empty() && !r[0][0].is_null()) return sql::to_uint(r[0][0]);
  return std::nullopt;
}

unsigned long long RobotChannel::connection_id() {
  mysqlpp::Query q = c_.query("SELECT CONNECTION_ID()");
  return sql::to_uint(q.store()[0][0]);
}

bool RobotChannel::session_alive(unsigned long long connection_id) {
  mysqlpp::Query q = c_.query();
  q << "SELECT COUNT(*) FROM information_schema.PROCESSLIST WHERE ID = " << connection_id;
  return sql::to_uint(q.store()[0][0]) > 0;
}

void RobotChannel::causal_reads(bool on) {
  try {
    mysqlpp::Query q = c_.query();
    q << "SET SESSION wsrep_sync_wait = " << (on ? 1 : 0);
    q.execute();
  } catch (const mysqlpp::BadQuery& e) {
    if (e.errnum() != 1193) throw;  // 1193: unknown variable, a MariaDB without wsrep
  }
}

void RobotChannel::limit_lock_waits(unsigned seconds) {
  mysqlpp::Query q = c_.query();
  q << "SET SESSION innodb_lock_wait_timeout = " << seconds;
  q.execute();
}

}  // namespace fleetmap
