#pragma once
// One multi-row INSERT built row by row and run every kRows rows and at the end: an
// import of thousands of rows in a few round trips (topologies, scenes).
#include <string>

#include <mysql++/mysql++.h>

namespace fleetmap {

class BatchInsert {
 public:
  static constexpr size_t kRows = 1000;

  // head: "INSERT INTO t (a, b) VALUES "
  BatchInsert(mysqlpp::Connection& c, std::string head) : q_(c.query()), head_(std::move(head)) {}

  // The query to write one "(...)" row into; call end_row() after it.
  mysqlpp::Query& row() {
    if (rows_++ == 0) {
      q_.reset();
      q_ << head_;
    } else {
      q_ << ",";
    }
    return q_;
  }
  void end_row() {
    if (rows_ == kRows) flush();
  }
  void flush() {
    if (rows_ == 0) return;
    q_.execute();
    rows_ = 0;
  }

 private:
  mysqlpp::Query q_;
  std::string head_;
  size_t rows_ = 0;
};

}  // namespace fleetmap
