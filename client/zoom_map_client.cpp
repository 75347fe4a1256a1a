#include "client/zoom_map_client.h"

#include <spdlog/spdlog.h>

#include "protocol/map_codec.h"

namespace fleetmap {

ZoomMap::Reason ZoomMapClient::update(Point pose, double now_s) {
  if (pending_) return ZoomMap::Reason::None;
  const ZoomMap::Reason why = zoom_.needs_refresh(pose, now_s);
  if (why == ZoomMap::Reason::None) return why;
  const double w = zoom_.options().window_m;
  pending_ = client_.send(RequestOp::GetMap,
                          Json{{"x", pose.x}, {"y", pose.y}, {"w", w}, {"h", w}, {"encoding", std::string(name(encoding_))}});
  pending_centre_ = pose;
  return why;
}

bool ZoomMapClient::on_answer(const ReceivedAnswer& a, double now_s) {
  if (!pending_ || a.request_id != pending_) return false;
  pending_.reset();
  if (a.op != "SetMap") {
    // e.g. the window left the map: try again later, not in a tight loop.
    spdlog::warn("zoom map: GetMap answered {} {}", a.op, a.params.dump());
    zoom_.on_window(pending_centre_, now_s);
    return false;
  }
  const SetMapParams p = decode_set_map(a.params);
  window_ = decode_map(a.payload.value_or(""), p.encoding, MapKind::Window);
  zoom_.on_window(pending_centre_, now_s);
  return true;
}

}  // namespace fleetmap
