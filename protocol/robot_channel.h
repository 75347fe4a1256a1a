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
  // Answers with id > after, in id order (at most limit).
  std::vector<ReceivedAnswer> answers(unsigned long long after, size_t limit);
  void remove(unsigned long long answer_id);

 private:
  mysqlpp::Connection& c_;
};

}  // namespace fleetmap
