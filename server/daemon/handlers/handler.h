#pragma once
// One handler per robot op (SPEC 5.2). A handler gets the decoded request and the robot
// it came from (its robots row locked by this server), does the work through the table
// classes of protocol/, and adds answers; a ProtocolError becomes an Error answer.
//
// Batching (issue 4): what a request writes to sa, trajectories and gps_fixes goes into
// ctx.writes, and the robot's own row is changed in memory (ctx.robot); the request loop
// writes both once per batch (protocol/write_batch.h). Rarer changes (tasks, sessions,
// images, objects) go to the database at once. A handler throws a ProtocolError only
// before its first direct write, so that the Error needs no savepoint to undo anything.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "protocol/map_store.h"
#include "protocol/params.h"
#include "protocol/request_queue.h"
#include "protocol/robot_store.h"
#include "protocol/write_batch.h"
#include "server/core/map_cache.h"
#include "server/core/planner_cache.h"
#include "server/core/server_config.h"

namespace fleetmap {

// A robot claimed for one batch: its row and open task as loaded at claim time, kept up
// to date by the handlers.
struct RobotSession {
  RobotRow robot;
  std::optional<TaskRow> open_task;
};

// Map descriptions looked up during one batch (every GetMap and SendGPS needs one).
class MapInfoCache {
 public:
  const std::optional<MapInfo>& get(MapStore& maps, unsigned map_id) {
    auto it = infos_.find(map_id);
    if (it == infos_.end()) it = infos_.emplace(map_id, maps.info(map_id)).first;
    return it->second;
  }

 private:
  std::map<unsigned, std::optional<MapInfo>> infos_;
};

struct HandlerContext {
  const ServerConfig& config;
  RobotStore& robots;
  MapStore& maps;
  MapCache& map_cache;
  PlannerCache& planners;
  MapInfoCache& map_infos;
  RobotSession& session;
  RobotRow& robot;  // session.robot
  const Request& request;
  Json params;
  RequestWrites writes;

  void answer(AnswerOp op, Json p, std::optional<std::string> payload = std::nullopt) {
    writes.answers.push_back({robot.id, robot.db_user, request.id, op, std::move(p), std::move(payload)});
  }
  void op_ack() { answer(AnswerOp::OpAck, encode_op_ack(request.id)); }

  std::optional<MapInfo> map_info() {
    if (!robot.map_id) return std::nullopt;
    return map_infos.get(maps, *robot.map_id);
  }
  const std::optional<TaskRow>& open_task() const { return session.open_task; }
  // Writes the new state at once and keeps session.open_task in step.
  void set_task_state(unsigned long long task_id, const std::string& state);
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
