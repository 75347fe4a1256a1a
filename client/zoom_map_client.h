#pragma once
// Keeps the robot's current map window up to date through RobotClient: asks GetMap when
// ZoomMap says so, installs the SetMap that answers it. The caller feeds it the pose
// estimate and the answers it receives.
#include <optional>

#include "client/robot_client.h"
#include "client/zoom_map.h"

namespace fleetmap {

class ZoomMapClient {
 public:
  ZoomMapClient(RobotClient& client, ZoomMapOptions options, MapEncoding encoding = MapEncoding::Seed)
      : client_(client), zoom_(options), encoding_(encoding) {}

  // Sends GetMap when needed and none is pending; returns why it asked (None: it did not).
  ZoomMap::Reason update(Point pose, double now_s);

  // Takes the SetMap (or Error) that answers our GetMap; true when a new window is in place.
  bool on_answer(const ReceivedAnswer& a, double now_s);

  const std::optional<Map>& window() const { return window_; }
  bool pending() const { return pending_.has_value(); }
  const ZoomMap& zoom() const { return zoom_; }

 private:
  RobotClient& client_;
  ZoomMap zoom_;
  MapEncoding encoding_;
  std::optional<unsigned long long> pending_;  // request id of our GetMap
  Point pending_centre_;
  std::optional<Map> window_;
};

}  // namespace fleetmap
