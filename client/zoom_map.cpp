#include "client/zoom_map.h"

namespace fleetmap {

ZoomMap::Reason ZoomMap::needs_refresh(Point pose, double now_s) const {
  if (!centre_) return Reason::NoWindow;
  if (distance(pose, *centre_) >= o_.refresh_distance_m) return Reason::Distance;
  if (now_s - since_s_ >= o_.refresh_after_s) return Reason::Timeout;
  return Reason::None;
}

void ZoomMap::on_window(Point centre, double now_s) {
  centre_ = centre;
  since_s_ = now_s;
}

}  // namespace fleetmap
