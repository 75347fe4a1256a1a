#pragma once
// One handler per robot op (SPEC 5.2). A handler gets the decoded request and the robot
// it came from (its robots row locked by this server), does the work through the table
// classes of protocol/, and adds answers; a ProtocolError becomes an Error answer.
#include <optional>
#include <string>
#include <vector>

#include "protocol/map_store.h"
#include "protocol/params.h"
#include "protocol/request_queue.h"
#include "protocol/robot_store.h"
#include "server/map_cache.h"
#include "server/planner_cache.h"
#include "server/server_config.h"

namespace fleetmap {

struct HandlerContext {
  const ServerConfig& config;
  RobotStore& robots;
  MapStore& maps;
  MapCache& map_cache;
  PlannerCache& planners;
  RobotRow& robot;
  const Request& request;
  Json params;
  std::vector<Answer> answers;

  void answer(AnswerOp op, Json p, std::optional<std::string> payload = std::nullopt) {
    answers.push_back({robot.id, robot.db_user, request.id, op, std::move(p), std::move(payload)});
  }
  void op_ack() { answer(AnswerOp::OpAck, encode_op_ack(request.id)); }
};

using Handler = void (*)(HandlerContext&);

// The handler of an op (every op has one).
Handler handler_for(RequestOp op);

void handle_ready(HandlerContext&);
void handle_alive(HandlerContext&);
void handle_stopped(HandlerContext&);
void handle_op_ack(HandlerContext&);
void handle_send_pos(HandlerContext&);
void handle_send_gps(HandlerContext&);
void handle_send_image(HandlerContext&);
void handle_get_map(HandlerContext&);
void handle_get_path(HandlerContext&);
void handle_get_pos_ini(HandlerContext&);
void handle_get_pos_end(HandlerContext&);
void handle_set_object(HandlerContext&);

// SetMap for a window of the robot's map (shared by Ready and GetMap).
void answer_map(HandlerContext& ctx, const Rect* window, MapEncoding encoding);

}  // namespace fleetmap
