#pragma once
// The server's side of the rr/sa tables (SPEC 5.1, 5.3): the one place that writes SQL
// against them for the server. Used inside the caller's transaction.
#include <optional>
#include <string>
#include <vector>

#include <mysql++/mysql++.h>

#include "protocol/params.h"

namespace fleetmap {

struct Request {
  unsigned long long id = 0;
  std::optional<unsigned> robot_id;  // as the robot wrote it (never trusted)
  std::string db_user;               // set by the database (trigger rr_stamp)
  std::string op;
  std::string params;
  std::optional<std::string> payload;
  std::string created_at;
};

struct Answer {
  unsigned robot_id = 0;
  std::string db_user;
  std::optional<unsigned long long> request_id;
  AnswerOp op = AnswerOp::Error;
  Json params;
  std::optional<std::string> payload;
};

class RequestQueue {
 public:
  explicit RequestQueue(mysqlpp::Connection& c) : c_(c) {}

  // Accounts with waiting requests, the longest-waiting first (a plain read: no locks);
  // with modulus > 1 only those of robots whose id mod modulus is remainder (a server's
  // share of the fleet, server/core/robot_partition.h).
  std::vector<std::string> waiting_accounts(size_t limit, unsigned modulus = 1, unsigned remainder = 0);

  // The oldest requests of these accounts in id order: at most per_account of each (a
  // prefix of each account's queue) and total in all.
  std::vector<Request> requests_of(const std::vector<std::string>& accounts, size_t per_account, size_t total);
  // The same as SQL and its result, for a caller that sends it with other statements in
  // one round trip (server/daemon/request_loop.cpp); accounts not empty.
  std::string requests_sql(const std::vector<std::string>& accounts, size_t total);
  static std::vector<Request> requests_from(const mysqlpp::StoreQueryResult& res, size_t per_account);

  unsigned long long insert(const Answer& a);  // the sa.id
  void remove(const std::vector<unsigned long long>& request_ids);

 private:
  mysqlpp::Connection& c_;
};

}  // namespace fleetmap
