#pragma once
// Robots' reported poses as tracks (common/io/trajectory_geojson.h), with their UTC times:
// what `fleetmap trajectory`, `fleetmap map export --trajectories` and the web API's
// trajectory route write.
#include <optional>
#include <string>
#include <vector>

#include "common/io/trajectory_geojson.h"
#include "protocol/fleet_store.h"

namespace fleetmap {

// A robot's reported poses, in time order; since as FleetStore::trajectory takes it
// ('2026-11-28 07:00:00' or an age: '10m'). Throws RobotNotFound.
Track load_track(FleetStore& fleet, const std::string& robot, const std::optional<std::string>& since);
// Those of every robot on the map (robots with no pose are left out).
std::vector<Track> load_map_tracks(FleetStore& fleet, const std::string& map, const std::optional<std::string>& since);

}  // namespace fleetmap
