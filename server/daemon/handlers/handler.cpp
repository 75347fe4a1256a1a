#include "server/daemon/handlers/handler.h"

#include "common/map/map_window.h"
#include "protocol/map_codec.h"

namespace fleetmap {

bool HandlerContext::task_event(const TaskRow& task, TaskEvent event, const std::string& reason) {
  const TaskTransition t = task_transition(task.state, event);
  if (!t) return false;
  records.set_task_state(task.id, t.next(), reason);
  if (served.open_task && served.open_task->id == task.id) {
    if (is_open(t.next())) served.open_task->state = t.next();
    else served.open_task.reset();  // closed: a robot has one open task at most
  }
  return true;
}

Handler handler_for(RequestOp op) {
  switch (op) {
    case RequestOp::Ready: return handle_ready;
    case RequestOp::Alive: return handle_alive;
    case RequestOp::Stopped: return handle_stopped;
    case RequestOp::OpAck: return handle_op_ack;
    case RequestOp::SendPos: return handle_send_pos;
    case RequestOp::SendGPS: return handle_send_gps;
    case RequestOp::SendImage: return handle_send_image;
    case RequestOp::GetMap: return handle_get_map;
    case RequestOp::GetPath: return handle_get_path;
    case RequestOp::GetPosIni: return handle_get_pos_ini;
    case RequestOp::GetPosEnd: return handle_get_pos_end;
    case RequestOp::SetObject: return handle_set_object;
    case RequestOp::TourEvent: return handle_tour_event;
  }
  return nullptr;
}

MapInfo robot_map_info(HandlerContext& ctx) {
  if (!ctx.robot.map_id)
    throw ProtocolError(ErrorCode::Internal, "no map is assigned to this robot; ask an operator (fleetmap robot add --map)");
  std::optional<MapInfo> info = ctx.map_info();
  if (!info) throw ProtocolError(ErrorCode::Internal, "the robot's map was deleted; ask an operator");
  return std::move(*info);
}

void answer_map(HandlerContext& ctx, const Rect* window, MapEncoding encoding) {
  const MapInfo info = robot_map_info(ctx);
  std::optional<Rect> r;
  if (window) {
    r = intersection(*window, info.border.rect());
    if (r->empty()) throw ProtocolError(ErrorCode::BadParams, "params: expected a window that overlaps the map's border");
  }
  // The map the robot's laser sees (seed 004 section III.A); without a laser height in
  // its profile, the stored map unsliced (server/daemon/robot_map_source.h).
  const std::optional<double> laser_height = ctx.robot.laser_height;
  const Map m = ctx.maps.robot_map(info, r, laser_height);
  SetMapParams p = set_map_params(m, encoding);
  p.laser_height = laser_height;
  ctx.answer(AnswerOp::SetMap, encode(p), encode_map(m, encoding));
}

}  // namespace fleetmap
