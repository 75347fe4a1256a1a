#pragma once
// decode -> handler -> answer (SPEC 5.2, 5.3), each step callable alone and without a
// database: dispatch() serves one request of a claimed robot, serve_requests() a batch's
// requests in id order. The request loop (request_loop.h) claims the robots, runs these
// over MariaDB and commits; the handler tests run them over in-memory stores.
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "protocol/request_queue.h"
#include "protocol/write_batch.h"
#include "server/core/server_config.h"
#include "server/daemon/handlers/handler.h"

namespace fleetmap {

// One request: the checks every op shares (a known op; robot_id, when given, the
// account's own robot; Ready before anything else), the params parsed as a JSON object,
// then the op's handler. A ProtocolError becomes the Error answer to the request, and
// the robot and its open task are left as they were before it. Other exceptions
// (database errors, bugs) propagate: only the caller can undo direct writes.
RequestWrites dispatch(const ServerConfig& config, RobotRecords& records, RobotMaps& maps, ServedRobot& served,
                       const Request& request);

// The Error answer to a request.
RequestWrites error_answer(const RobotRow& robot, const Request& request, ErrorCode code, const std::string& message);

// Where a batch's results go: the request loop's WriteBatch, a vector in tests.
class BatchSink {
 public:
  virtual ~BatchSink() = default;
  // The request is served (its writes, possibly none) and leaves rr.
  virtual void served(const Request& request, RequestWrites&& writes) = 0;
  // A robot's row as the batch leaves it, seen last when its last request was made.
  virtual void robot_seen(const RobotRow& robot, const std::string& last_seen) = 0;
};

using RequestHandler = std::function<RequestWrites(ServedRobot&, const Request&)>;

// Every request (in id order, each of a robot in `robots`, keyed by db_user) through
// handle, except those of removed robots, which only leave rr; then the row of each
// robot that had requests, with its last request's time as last_seen. A lost robot
// that sent anything is ready again (SPEC 5.3).
void serve_requests(std::map<std::string, ServedRobot>& robots, const std::vector<Request>& requests,
                    const RequestHandler& handle, BatchSink& sink);

}  // namespace fleetmap
