#include "protocol/request_queue.h"

#include <algorithm>
#include <map>

#include "protocol/sql_util.h"

namespace fleetmap {

std::vector<std::string> RequestQueue::waiting_accounts(size_t limit, unsigned modulus, unsigned remainder) {
  // The head of the queue by primary key, deduplicated here: a GROUP BY over all of rr
  // costs more the longer the queue grows, just when the server is behind
  // (fleetmap-loadgen: 11 ms at 4 700 waiting rows, against 0.2 ms for this).
  mysqlpp::Query q = c_.query();
  if (modulus > 1)
    // rr's primary key in order, each row's robot by uq_robots_db_user: the head of this
    // share's queue, however long the other shares' queues are.
    q << "SELECT rr.db_user FROM rr STRAIGHT_JOIN robots b ON b.db_user = rr.db_user WHERE TRUE"
      << sql::share_condition("b.id", modulus, remainder) << " ORDER BY rr.id LIMIT " << limit * 16;
  else
    q << "SELECT db_user FROM rr ORDER BY id LIMIT " << limit * 16;
  std::vector<std::string> out;
  for (const mysqlpp::Row& r : q.store()) {
    std::string user = sql::to_string(r[0]);
    if (std::find(out.begin(), out.end(), user) == out.end()) out.push_back(std::move(user));
    if (out.size() >= limit) break;
  }
  return out;
}

namespace {

constexpr const char* kRequestColumns = "id, robot_id, db_user, op, params, payload, created_at";

Request read_request(const mysqlpp::Row& r) {
  Request req;
  req.id = sql::to_uint(r[0]);
  if (!r[1].is_null()) req.robot_id = static_cast<unsigned>(sql::to_uint(r[1]));
  req.db_user = sql::to_string(r[2]);
  req.op = sql::to_string(r[3]);
  req.params = sql::to_string(r[4]);
  if (!r[5].is_null()) req.payload = sql::to_string(r[5]);
  req.created_at = sql::to_string(r[6]);
  return req;
}

}  // namespace

std::vector<Request> RequestQueue::requests_of(const std::vector<std::string>& accounts, size_t per_account,
                                               size_t total) {
  if (accounts.empty()) return {};
  mysqlpp::Query q = c_.query(requests_sql(accounts, total));
  return requests_from(q.store(), per_account);
}

std::string RequestQueue::requests_sql(const std::vector<std::string>& accounts, size_t total) {
  mysqlpp::Query q = c_.query();
  q << "SELECT " << kRequestColumns << " FROM rr WHERE db_user IN (";
  for (size_t i = 0; i < accounts.size(); ++i) q << (i ? "," : "") << mysqlpp::quote << accounts[i];
  q << ") ORDER BY id LIMIT " << total;
  return q.str();
}

std::vector<Request> RequestQueue::requests_from(const mysqlpp::StoreQueryResult& res, size_t per_account) {
  std::vector<Request> out;
  std::map<std::string, size_t> taken;
  for (const mysqlpp::Row& r : res) {
    Request req = read_request(r);
    // Past an account's share, its later requests wait for the next batch: what is taken
    // stays a prefix of its queue, in id order.
    if (++taken[req.db_user] > per_account) continue;
    out.push_back(std::move(req));
  }
  return out;
}

unsigned long long RequestQueue::insert(const Answer& a) {
  mysqlpp::Query q = c_.query();
  q << "INSERT INTO sa (robot_id, db_user, request_id, op, params, payload, created_at) VALUES (" << a.robot_id << ", "
    << mysqlpp::quote << a.db_user << ", ";
  if (a.request_id) q << *a.request_id;
  else q << "NULL";
  // replace: an error message may quote a robot's invalid UTF-8; it must not stop the answer.
  q << ", " << mysqlpp::quote << std::string(name(a.op)) << ", " << mysqlpp::quote
    << a.params.dump(-1, ' ', false, Json::error_handler_t::replace) << ", ";
  if (a.payload) q << mysqlpp::quote << *a.payload;
  else q << "NULL";
  q << ", SYSDATE(6))";
  return q.execute().insert_id();
}

void RequestQueue::remove(const std::vector<unsigned long long>& ids) {
  if (ids.empty()) return;
  mysqlpp::Query q = c_.query();
  q << "DELETE FROM rr WHERE id IN (";
  for (size_t i = 0; i < ids.size(); ++i) q << (i ? "," : "") << ids[i];
  q << ")";
  q.execute();
}

}  // namespace fleetmap
