#include "server/core/server_config.h"

#include <stdexcept>

#include "app/config_number.h"

namespace fleetmap {
namespace {

double number(const std::string& key, const std::string& v, bool zero_ok) {
  return config_number("[server]", key, v, zero_ok);
}

double positive(const std::string& key, const std::string& v) { return number(key, v, false); }

// Counts (threads, robots, bytes): a whole number, so that "1.5" workers is refused
// rather than cut to 1.
size_t count(const std::string& key, const std::string& v, double most = 1e15) {
  return config_whole("[server]", key, v, 1, most);
}

}  // namespace

void ServerConfig::apply(const std::map<std::string, std::string>& s) {
  for (const auto& [k, v] : s) {
    if (k == "alive_period_s") alive_period_s = positive(k, v);
    else if (k == "lost_after_periods") lost_after_periods = positive(k, v);
    else if (k == "workers") workers = static_cast<int>(count(k, v, 1024));
    else if (k == "poll_max_ms") poll_max_ms = positive(k, v);
    else if (k == "batch_robots") batch_robots = count(k, v);
    else if (k == "batch_requests") batch_requests = count(k, v);
    else if (k == "max_full_map_segments") max_full_map_segments = count(k, v);
    else if (k == "ready_window_m") ready_window_m = positive(k, v);
    else if (k == "max_window_m") max_window_m = positive(k, v);
    else if (k == "max_image_bytes") max_image_bytes = count(k, v);
    else if (k == "goal_tolerance_m") goal_tolerance_m = positive(k, v);
    else if (k == "robot_radius_m") robot_radius_m = positive(k, v);
    else if (k == "body_height_m") body_height_m = positive(k, v);
    else if (k == "topo_path_min_m") topo_path_min_m = number(k, v, true);
    else if (k == "object_ttl_s") object_ttl_s = positive(k, v);
    else if (k == "history_keep_s") {
      // A cutoff in microseconds must fit the database's interval; a century is beyond any site.
      const double keep = number(k, v, true);
      if (keep > kMaxHistoryKeepS)
        throw std::invalid_argument("[server] history_keep_s: expected seconds up to 100 years (3155760000), got '" +
                                    v + "'");
      history_keep_s = keep;
    }
    else if (k == "commit_delay_ms") commit_delay_ms = number(k, v, true);
    else if (k == "robot_block_ms") robot_block_ms = positive(k, v);
    else if (k == "partition") partition = parse_robot_partition(v);
    else if (k == "lock_wait_timeout_s") lock_wait_timeout_s = static_cast<int>(count(k, v, 3600));
    else throw std::invalid_argument("[server] unknown setting '" + k + "'");
  }
}

}  // namespace fleetmap
