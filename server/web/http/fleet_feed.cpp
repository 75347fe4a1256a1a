#include "server/web/http/fleet_feed.h"

#include <chrono>

#include <spdlog/spdlog.h>

#include "protocol/connection.h"
#include "protocol/fleet_store.h"
#include "protocol/map_store.h"
#include "protocol/task_changes.h"
#include "server/web/api/fleet_json.h"

namespace fleetmap::web {

std::vector<nlohmann::json> RobotDiff::changed(const std::vector<nlohmann::json>& now) {
  std::vector<nlohmann::json> out;
  for (const auto& r : now) {
    auto& last = last_[r.value("name", std::string())];
    if (last != r) {
      last = r;
      out.push_back(r);
    }
  }
  return out;
}

void FleetFeed::start() {
  stop_ = false;
  thread_ = std::thread([this] { run(); });
}

void FleetFeed::stop() {
  stop_ = true;
  if (thread_.joinable()) thread_.join();
}

void FleetFeed::run() {
  const auto period = std::chrono::milliseconds(period_ms_);
  std::unique_ptr<mysqlpp::Connection> c;
  auto backoff = std::chrono::milliseconds(250);
  while (!stop_) {
    const auto started = std::chrono::steady_clock::now();
    try {
      if (!c || !c->ping()) {
        c = connect(web_);
        // Times in UTC, so that last_seen and the tasks' times read as ISO 8601 UTC.
        execute(*c, "SET time_zone = '+00:00'");
        if (tasks_since_.empty()) tasks_since_ = database_now(*c);
        backoff = std::chrono::milliseconds(250);
      }
      poll(*c);
    } catch (const std::exception& e) {
      spdlog::warn("feed: {}; retrying in {} ms", e.what(), backoff.count());
      c.reset();
      for (auto until = std::chrono::steady_clock::now() + backoff; !stop_ && std::chrono::steady_clock::now() < until;)
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
      backoff = std::min(backoff * 2, std::chrono::milliseconds(5000));
      continue;
    }
    // A fixed period from the start of each poll: at most one robots message per period.
    const auto next = started + period;
    while (!stop_ && std::chrono::steady_clock::now() < next)
      std::this_thread::sleep_for(std::min<std::chrono::steady_clock::duration>(next - std::chrono::steady_clock::now(),
                                                                                std::chrono::milliseconds(20)));
  }
}

void FleetFeed::poll(mysqlpp::Connection& c) {
  // Georeferences change rarely (fleetmap map georef): reread about every 2 s; a
  // transform is built once per georeference (PROJ's setup is the costly part).
  if (const auto now = std::chrono::steady_clock::now(); now >= maps_due_) {
    maps_due_ = now + std::chrono::seconds(2);
    std::map<std::string, Georef> next;
    for (const MapInfo& m : MapStore(c).list()) {
      auto old = georefs_.find(m.name);
      // Rebuilt when the map was replaced or georeferenced anew (same revision).
      if (old != georefs_.end() && old->second.revision == m.revision && old->second.georef == m.georef) {
        next[m.name] = old->second;
        continue;
      }
      Georef g{m.revision, m.georef, nullptr};
      if (m.georef) {
        try {
          g.transform = std::make_shared<GeoTransform>(*m.georef);
        } catch (const std::exception& e) {
          spdlog::warn("feed: map {}: its georeference cannot be used: {}", m.name, e.what());
        }
      }
      next[m.name] = std::move(g);
    }
    georefs_ = std::move(next);
  }

  FeedUpdate update;
  std::vector<nlohmann::json> robots;
  for (const RobotStatus& s : FleetStore(c).status()) {
    std::optional<LonLat> ll;
    if (s.x && s.y) ll = lonlat(s.map, *s.x, *s.y);
    robots.push_back(robot_state_json(s, ll));
  }
  update.robots = diff_.changed(robots);
  // Two seconds back, for late commits; what was pushed with the same updated_at is not
  // pushed again, and what the window no longer returns cannot come back unchanged.
  std::map<unsigned long long, std::string> seen;
  for (const TaskInfo& t : tasks_updated_since(c, tasks_since_, 2'000'000)) {
    auto old = tasks_seen_.find(t.id);
    if (old == tasks_seen_.end() || old->second != t.updated_at) update.tasks.push_back(task_json(t));
    seen[t.id] = t.updated_at;
    if (t.updated_at > tasks_since_) tasks_since_ = t.updated_at;
  }
  tasks_seen_ = std::move(seen);
  hub_.publish(update);
}

std::optional<LonLat> FleetFeed::lonlat(const std::string& map, double x, double y) const {
  auto it = georefs_.find(map);
  if (it == georefs_.end() || !it->second.transform) return std::nullopt;
  try {
    return it->second.transform->to_wgs84({x, y});
  } catch (const std::exception&) {
    return std::nullopt;  // outside the CRS's domain
  }
}

}  // namespace fleetmap::web
