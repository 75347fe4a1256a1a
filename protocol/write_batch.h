#pragma once
// The server's writes of one batch of requests, sent together (SPEC 8: throughput).
// Handlers describe what a request writes (answers, trajectory points, GPS fixes) in a
// RequestWrites; the loop adds it to the batch once the request succeeded, with each
// claimed robot's final row, and flush() sends every row as multi-row statements and the
// COMMIT in one round trip. Same transaction, same exactly-once guarantee as writing each
// row at once; a few statements per batch instead of several per request.
#include <optional>
#include <string>
#include <vector>

#include <mysql++/mysql++.h>

#include "common/geometry/geometry.h"
#include "protocol/params.h"
#include "protocol/request_queue.h"
#include "protocol/robot_store.h"

namespace fleetmap {

struct PoseReport {
  unsigned robot_id = 0;
  SendPosParams pose;
  std::string at;  // the request's created_at
};

struct GpsReport {
  unsigned robot_id = 0;
  SendGpsParams fix;
  std::optional<Point> map_xy;  // when the map is georeferenced
  std::string at;
};

// What one request writes besides direct table changes; dropped when it fails.
struct RequestWrites {
  std::vector<Answer> answers;
  std::vector<PoseReport> poses;
  std::vector<GpsReport> fixes;
  // The request was refused (a ProtocolError's Error answer): its handler wrote nothing
  // at once. An Error a handler answers itself after a direct write (GetPath's no_path
  // failing the task) is not a refusal.
  bool refused = false;
  void clear() {
    answers.clear();
    poses.clear();
    fixes.clear();
    refused = false;
  }
};

class WriteBatch {
 public:
  // multi_statements: the connection was opened with them (connect(..., true)); without,
  // each statement is its own round trip.
  WriteBatch(mysqlpp::Connection& c, bool multi_statements) : c_(c), multi_(multi_statements) {}

  void add(RequestWrites&& w);
  // A claimed robot's row as the batch leaves it: pose, state, last_seen.
  void robot(const RobotRow& r, const std::string& last_seen);
  void remove_request(unsigned long long id) { removed_.push_back(id); }

  // Sends what is pending; with commit, the COMMIT goes in the same round trip. A
  // failing statement stops the rest (so no COMMIT) and throws mysqlpp::BadQuery.
  void flush(bool commit);

 private:
  std::vector<std::string> statements();

  mysqlpp::Connection& c_;
  bool multi_;
  std::vector<Answer> answers_;
  std::vector<PoseReport> poses_;
  std::vector<GpsReport> fixes_;
  std::vector<std::string> robot_updates_;
  std::vector<unsigned long long> removed_;
};

}  // namespace fleetmap
