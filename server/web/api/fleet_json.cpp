#include "server/web/api/fleet_json.h"

#include "common/core/error.h"
#include "common/gis/wgs84_frame.h"
#include "protocol/map_store.h"
#include "server/web/api/utc_session.h"

namespace fleetmap::web {
namespace {

nlohmann::json number_or_null(const std::optional<double>& v) { return v ? nlohmann::json(*v) : nlohmann::json(); }

nlohmann::json text_or_null(const std::string& s) { return s.empty() ? nlohmann::json() : nlohmann::json(s); }

nlohmann::json states_of(const std::vector<RobotStatus>& all, const std::map<std::string, OutputFrame>& frames) {
  nlohmann::json out = nlohmann::json::array();
  for (const RobotStatus& s : all) {
    auto it = frames.find(s.map);
    out.push_back(robot_state_json(s, it == frames.end() ? nullptr : &it->second));
  }
  return out;
}

}  // namespace

std::map<std::string, OutputFrame> wgs84_frames(mysqlpp::Connection& c) {
  std::map<std::string, OutputFrame> out;
  for (const MapInfo& m : MapStore(c).list()) {
    if (!m.georef) continue;
    try {
      out.emplace(m.name, wgs84_frame(*m.georef));
    } catch (const BadInput&) {
      // PROJ refuses this georeference: the map's robots have no lonlat, the rest still do
    }
  }
  return out;
}

nlohmann::json robot_state_json(const RobotStatus& s, const OutputFrame* wgs84) {
  std::optional<LonLat> lonlat;
  if (wgs84 && s.x && s.y) {
    try {
      const Point p = wgs84->apply({*s.x, *s.y});
      lonlat = LonLat{p.x, p.y};
    } catch (const std::invalid_argument&) {
      // outside the projection's domain: no lonlat
    }
  }
  return robot_state_json(s, lonlat);
}

nlohmann::json robot_state_json(const RobotStatus& s, const std::optional<LonLat>& lonlat) {
  nlohmann::json task;
  if (s.task_id)
    task = {{"id", *s.task_id},
            {"state", s.task_state ? nlohmann::json(std::string(to_string(*s.task_state))) : nlohmann::json()}};
  nlohmann::json goal;
  if (s.goal_x && s.goal_y) goal = {*s.goal_x, *s.goal_y};
  return {{"name", s.name},
          {"map", text_or_null(s.map)},
          {"state", std::string(to_string(s.state))},
          {"x", number_or_null(s.x)},
          {"y", number_or_null(s.y)},
          {"theta", number_or_null(s.theta)},
          {"v", number_or_null(s.v)},
          {"lonlat", lonlat ? nlohmann::json::array({lonlat->lon, lonlat->lat}) : nlohmann::json()},
          {"task", task},
          {"goal", goal},
          {"last_seen", text_or_null(iso8601_utc(s.last_seen))}};
}

nlohmann::json task_json(const TaskInfo& t) {
  return {{"id", t.id},
          {"robot", t.robot},
          {"state", std::string(to_string(t.state))},
          {"goal", {t.goal_x, t.goal_y}},
          {"created_at", iso8601_utc(t.created_at)},
          {"updated_at", iso8601_utc(t.updated_at)},
          {"reason", t.reason}};
}

nlohmann::json read_robot_states(mysqlpp::Connection& c) {
  const std::map<std::string, OutputFrame> frames = wgs84_frames(c);
  const UtcSession utc(c);
  return states_of(FleetStore(c).status(), frames);
}

nlohmann::json read_robot_state(mysqlpp::Connection& c, const std::string& robot) {
  const std::map<std::string, OutputFrame> frames = wgs84_frames(c);
  const UtcSession utc(c);
  for (const RobotStatus& s : FleetStore(c).status()) {
    if (s.name != robot) continue;
    auto it = frames.find(s.map);
    return robot_state_json(s, it == frames.end() ? nullptr : &it->second);
  }
  throw RobotNotFound(robot);
}

nlohmann::json read_tasks(mysqlpp::Connection& c, const std::optional<std::string>& robot, size_t limit) {
  const UtcSession utc(c);
  nlohmann::json out = nlohmann::json::array();
  for (const TaskInfo& t : FleetStore(c).tasks(robot, limit)) out.push_back(task_json(t));
  return out;
}

}  // namespace fleetmap::web
