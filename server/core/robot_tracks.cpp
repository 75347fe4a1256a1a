#include "server/core/robot_tracks.h"

namespace fleetmap {

Track load_track(FleetStore& fleet, const std::string& robot, const std::optional<std::string>& since) {
  Track t;
  t.robot = robot;
  for (const TrajectoryPoint& p : fleet.trajectory(robot, since)) t.poses.push_back({p.t_utc, {p.x, p.y}, p.theta, p.v});
  return t;
}

std::vector<Track> load_map_tracks(FleetStore& fleet, const std::string& map, const std::optional<std::string>& since) {
  std::vector<Track> out;
  for (const RobotStatus& r : fleet.status()) {
    if (r.map != map) continue;
    Track t = load_track(fleet, r.name, since);
    if (!t.poses.empty()) out.push_back(std::move(t));
  }
  return out;
}

}  // namespace fleetmap
