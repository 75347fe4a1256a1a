#pragma once
// The robot's side of rr/sa_mine (SPEC 5.1): insert a request, read this account's
// answers in id order, delete one. Plain statements a robot account is granted.
#include <optional>
#include <string>
#include <vector>

#include <mysql++/mysql++.h>

#include "protocol/params.h"

namespace fleetmap {

struct ReceivedAnswer {
  unsigned long long id = 0;
  unsigned robot_id = 0;
  std::optional<unsigned long long> request_id;
  std::string op;  // as stored; parse_answer_op() for the enum
  Json params;
  std::optional<std::string> payload;
};

class RobotChannel {
 public:
  explicit RobotChannel(mysqlpp::Connection& c) : c_(c) {}
  // The new request's id.
  unsigned long long send(RequestOp op, const Json& params, const std::optional<std::string>& payload,
                          std::optional<unsigned> robot_id);
  // The answers in sa_mine, in id order (at most limit). Not "after the last id read":
  // on a cluster an answer with a lower id can commit later (RobotClient::fetch).
  std::vector<ReceivedAnswer> answers(size_t limit);
  void remove(unsigned long long answer_id);

  // The highest id of this account's requests above `after` that the database holds,
  // waiting (rr_mine) or answered (sa_mine's request_id); nullopt: none. After a lost
  // connection, tells whether the INSERT in flight committed (SPEC 5.3): requests of one
  // robot get growing ids, so above the last acknowledged one can be only that one.
  std::optional<unsigned long long> request_after(unsigned long long after);

  // Galera: reads from now on wait until this node has applied every transaction the
  // cluster committed before them (wsrep_sync_wait), so that after moving to another node
  // the robot sees its own requests and answers. A no-op without Galera.
  void causal_reads(bool on);

  // A statement of this session waits at most `seconds` on a row lock, then fails with
  // 1205 and is rolled back whole (each robot statement is its own transaction). The
  // default of 50 s let one robot stall a Galera cluster: a replicated write waiting on
  // that robot's lock holds up every node (docs/galera.md, "A robot's lock wait").
  void limit_lock_waits(unsigned seconds);

  // This connection's id, and whether a connection of this id still runs on this node
  // (a robot sees its own sessions in the process list). A connection that broke, or that
  // the server ended, may still be committing its last statement there.
  unsigned long long connection_id();
  bool session_alive(unsigned long long connection_id);

 private:
  mysqlpp::Connection& c_;
};

}  // namespace fleetmap
