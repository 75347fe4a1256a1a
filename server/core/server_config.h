#pragma once
// The map server's own settings: defaults, then the [server] section of the config file,
// then flags (server_main.cpp). Documented in etc/fleetmap.conf.sample.
#include <map>
#include <string>

#include "server/core/robot_partition.h"

namespace fleetmap {

constexpr double kMaxHistoryKeepS = 100 * 365.25 * 86400;  // history_keep_s: a century

struct ServerConfig {
  double alive_period_s = 1.0;        // told to robots in Start
  double lost_after_periods = 5;      // silent this many periods -> lost
  int workers = 2;                    // threads, each with its own connection
  double poll_max_ms = 10;            // idle back-off ceiling when rr is empty
  size_t batch_robots = 16;           // robots claimed per transaction
  size_t batch_requests = 32;         // requests of one robot per transaction
  size_t max_full_map_segments = 20000;  // larger maps go out as a window on Ready
  double ready_window_m = 100;        // that window's side
  double max_window_m = 1000;         // GetMap w and h are capped to this
  size_t max_image_bytes = 8u << 20;  // SendImage payload limit
  double goal_tolerance_m = 0.5;      // Stopped within this of the goal -> task done
  double robot_radius_m = 0.3;        // GetPath plans for a disc of this radius (robots without a profile)
  double body_height_m = 1.0;         // elements starting below this block robots without a profile
  // GetPath plans through the map's topological graph when start and goal are at least
  // this far apart (straight line) and the map has one; 0: always. bench-topo-path,
  // docs/benchmarks.md ("GetPath through the graph") for the figures behind 60.
  double topo_path_min_m = 60;
  double object_ttl_s = 300;          // SetObject: an observation expires this long after its last sighting
  double history_keep_s = 0;          // trajectory rows and GPS fixes older than this are deleted; 0: kept
  int lock_wait_timeout_s = 1;        // then find and end the robot connection that blocks
  double robot_block_ms = 2000;       // a robot blocking another robot this long is ended (SPEC 5.3)
  double commit_delay_ms = 0;         // fault injection for crash tests: a wider window before COMMIT
  RobotPartition partition;           // the robots this server claims (several servers: disjoint shares)

  // Applies "key = value" settings; throws std::invalid_argument naming a bad key or value.
  void apply(const std::map<std::string, std::string>& settings);
};

}  // namespace fleetmap
