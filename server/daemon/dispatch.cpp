#include "server/daemon/dispatch.h"

#include <spdlog/spdlog.h>

#include "protocol/ops.h"

namespace fleetmap {

RequestWrites error_answer(const RobotRow& robot, const Request& request, ErrorCode code, const std::string& message) {
  RequestWrites w;
  w.answers.push_back({robot.id, robot.db_user, request.id, AnswerOp::Error,
                       encode(ErrorParams{request.id, code, message}), std::nullopt});
  w.refused = true;
  return w;
}

RequestWrites dispatch(const ServerConfig& config, RobotRecords& records, RobotMaps& maps, ServedRobot& served,
                       const Request& request) {
  const ServedRobot before = served;  // an Error leaves the robot as it was
  HandlerContext ctx(config, records, maps, served, request);
  const RobotRow& robot = served.robot;
  try {
    const std::optional<RequestOp> op = parse_request_op(request.op);
    if (!op) throw ProtocolError(ErrorCode::UnknownOp, "unknown op '" + request.op.substr(0, 16) + "'");
    if (request.robot_id && *request.robot_id != robot.id)
      throw ProtocolError(ErrorCode::NotYourRobot, "robot_id " + std::to_string(*request.robot_id) +
                                                       " is not this account's robot (" + std::to_string(robot.id) +
                                                       ")");
    if (*op != RequestOp::Ready && !robot.registered())
      throw ProtocolError(ErrorCode::NotRegistered, "send Ready first");
    ctx.params = parse_params(request.params);
    handler_for(*op)(ctx);
    return std::move(ctx.writes);
  } catch (const ProtocolError& e) {
    served = before;
    spdlog::debug("{} request {} ({}): {} {}", before.robot.db_user, request.id, request.op.substr(0, 16),
                  name(e.code()), e.what());
    return error_answer(before.robot, request, e.code(), e.what());
  }
}

void serve_requests(std::map<std::string, ServedRobot>& robots, const std::vector<Request>& requests,
                    const RequestHandler& handle, BatchSink& sink) {
  std::map<std::string, std::string> last_seen;
  for (const Request& req : requests) {
    ServedRobot& s = robots.at(req.db_user);
    sink.served(req, s.robot.removed ? RequestWrites{} : handle(s, req));
    last_seen[req.db_user] = req.created_at;  // requests come in id order
  }
  for (auto& [user, s] : robots) {
    if (s.robot.removed || !last_seen.count(user)) continue;  // another server took its requests
    if (s.robot.state == RobotState::Lost) s.robot.state = RobotState::Ready;  // anything it sends brings it back
    sink.robot_seen(s.robot, last_seen[user]);
  }
}

}  // namespace fleetmap
