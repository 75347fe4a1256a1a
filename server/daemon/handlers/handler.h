#pragma once
// One handler per robot op (SPEC 5.2). A handler gets the decoded request and the robot
// it came from (its robots row locked by this server), does the work through the small
// store interfaces of handler_stores.h, and adds answers; a ProtocolError becomes an
// Error answer (server/daemon/dispatch.h).
//
// Batching (SPEC 8, throughput): what a request writes to sa, trajectories and gps_fixes
// goes into ctx.writes, and the robot's own row is changed in memory (ctx.robot); the
// request loop writes both once per batch (protocol/write_batch.h). Rarer changes (tasks,
// sessions, images, objects) go to the database at once. A handler throws a
// ProtocolError only before its first direct write, so that the Error needs no
// savepoint to undo anything.
#include <optional>
#include <string>

#include "protocol/params.h"
#include "protocol/request_queue.h"
#include "protocol/robot_store.h"
#include "protocol/task_lifecycle.h"
#include "protocol/write_batch.h"
#include "server/core/server_config.h"
#include "server/daemon/handlers/handler_stores.h"

namespace fleetmap {

// A robot claimed for one batch: its row and open task as loaded at claim time, kept up
// to date by the handlers.
struct ServedRobot {
  RobotRow robot;
  std::optional<TaskRow> open_task;
};

struct HandlerContext {
  const ServerConfig& config;
  RobotRecords& records;
  RobotMaps& maps;
  ServedRobot& served;
  RobotRow& robot;  // served.robot
  const Request& request;
  Json params;
  RequestWrites writes;

  HandlerContext(const ServerConfig& c, RobotRecords& r, RobotMaps& m, ServedRobot& s, const Request& req)
      : config(c), records(r), maps(m), served(s), robot(s.robot), request(req) {}

  void answer(AnswerOp op, Json p, std::optional<std::string> payload = std::nullopt) {
    writes.answers.push_back({robot.id, robot.db_user, request.id, op, std::move(p), std::move(payload)});
  }
  void op_ack() { answer(AnswerOp::OpAck, encode_op_ack(request.id)); }

  std::optional<MapInfo> map_info() {
    if (!robot.map_id) return std::nullopt;
    return maps.info(*robot.map_id);
  }
  const std::optional<TaskRow>& open_task() const { return served.open_task; }

  // The event happened to this task (the robot's open one, or any of its tasks for
  // OpAck): when the life cycle allows it, the new state is written at once and
  // served.open_task kept in step (a closed task is no longer open). Returns whether
  // the task changed; a refused event leaves it as it is. A reason, when not empty, is
  // stored with the new state (tasks.reason).
  bool task_event(const TaskRow& task, TaskEvent event, const std::string& reason = "");
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
void handle_tour_event(HandlerContext&);

// The robot's map, or ProtocolError internal when it has none or it was deleted.
MapInfo robot_map_info(HandlerContext& ctx);

// SetMap for a window of the robot's map (shared by Ready and GetMap).
void answer_map(HandlerContext& ctx, const Rect* window, MapEncoding encoding);

}  // namespace fleetmap
