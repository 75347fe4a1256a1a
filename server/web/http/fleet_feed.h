#pragma once
// The WebSocket feed's source (docs/web-api.md "The feed"): one thread that polls the
// database every feed_period_ms with the web account, diffs the robots' states against
// the previous poll, reads the tasks changed since then, and hands both to the PushHub.
#include <atomic>
#include <chrono>
#include <map>
#include <optional>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include <mysql++/mysql++.h>
#include <nlohmann/json.hpp>

#include "common/gis/geo_transform.h"
#include "protocol/db_settings.h"
#include "server/web/http/push_hub.h"

namespace fleetmap::web {

// The robots whose state differs from the previous call's (by name); no database.
class RobotDiff {
 public:
  std::vector<nlohmann::json> changed(const std::vector<nlohmann::json>& now);

 private:
  std::map<std::string, nlohmann::json> last_;
};

class FleetFeed {
 public:
  FleetFeed(DbSettings web, int period_ms, PushHub& hub) : web_(std::move(web)), period_ms_(period_ms), hub_(hub) {}
  ~FleetFeed() { stop(); }
  void start();
  void stop();

 private:
  void run();
  void poll(mysqlpp::Connection& c);
  std::optional<LonLat> lonlat(const std::string& map, double x, double y) const;

  DbSettings web_;
  int period_ms_;
  PushHub& hub_;
  std::atomic<bool> stop_{false};
  std::thread thread_;
  RobotDiff diff_;
  std::string tasks_since_;  // the latest updated_at pushed
  std::map<unsigned long long, std::string> tasks_seen_;  // id -> updated_at pushed, within the look-back
  // Georeferenced maps by name: their revision and transform, reread every few seconds.
  struct Georef {
    unsigned revision = 0;
    std::optional<MapGeoref> georef;
    std::shared_ptr<GeoTransform> transform;  // null: not georeferenced (or PROJ refused it)
  };
  std::map<std::string, Georef> georefs_;
  std::chrono::steady_clock::time_point maps_due_{};  // the first poll reads them
};

}  // namespace fleetmap::web
