#include "server/daemon/handlers/handler.h"

#include "common/map/map_window.h"
#include "protocol/map_codec.h"
#include "server/daemon/robot_map_source.h"

namespace fleetmap {

void HandlerContext::set_task_state(unsigned long long task_id, const std::string& state) {
  robots.set_task_state(task_id, state);
  if (session.open_task && session.open_task->id == task_id) {
    if (state == "assigned" || state == "acknowledged" || state == "active") session.open_task->state = state;
    else session.open_task.reset();  // closed: a robot has one open task at most
  }
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
  }
  return nullptr;
}

void answer_map(HandlerContext& ctx, const Rect* window, MapEncoding encoding) {
  if (!ctx.robot.map_id)
    throw ProtocolError(ErrorCode::Internal, "no map is assigned to this robot; ask an operator (fleetmap robot add --map)");
  const std::optional<MapInfo> info = ctx.map_info();
  if (!info) throw ProtocolError(ErrorCode::Internal, "the robot's map was deleted; ask an operator");
  std::optional<Rect> r;
  if (window) {
    r = intersection(*window, info->border.rect());
    if (r->empty()) throw ProtocolError(ErrorCode::BadParams, "params: expected a window that overlaps the map's border");
  }
  // The map the robot's laser sees (issue 8); without a laser height in its profile, the
  // stored map as before (server/daemon/robot_map_source.h).
  const std::optional<double> laser_height = ctx.robot.laser_height;
  const Map m = RobotMapSource::shared().map(ctx.maps, ctx.map_cache, *info, r, laser_height);
  SetMapParams p = set_map_params(m, encoding);
  p.laser_height = laser_height;
  ctx.answer(AnswerOp::SetMap, encode(p), encode_map(m, encoding));
}

}  // namespace fleetmap
