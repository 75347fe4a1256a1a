#pragma once
// The zoom map of seed 002 (section 3.4): the robot keeps an area of interest around
// itself and asks for a new window (GetMap) when it has moved a given distance from the
// current window's centre, or when the window is older than a time-out (the world may
// have changed). Pure decision logic: no clock, no database.
#include <optional>

#include "common/geometry/geometry.h"

namespace fleetmap {

struct ZoomMapOptions {
  double window_m = 60;        // side of the requested window
  double refresh_distance_m = 15;  // moved this far from the centre -> new window
  double refresh_after_s = 60;     // window older than this -> new window
};

class ZoomMap {
 public:
  explicit ZoomMap(ZoomMapOptions o = {}) : o_(o) {}

  enum class Reason { None, NoWindow, Distance, Timeout };

  // Why a new window is needed at this pose and time (seconds on any monotonic clock).
  Reason needs_refresh(Point pose, double now_s) const;

  // A window centred on pose was asked for / received at now_s.
  void on_window(Point centre, double now_s);

  const ZoomMapOptions& options() const { return o_; }
  std::optional<Point> centre() const { return centre_; }

 private:
  ZoomMapOptions o_;
  std::optional<Point> centre_;
  double since_s_ = 0;
};

}  // namespace fleetmap
