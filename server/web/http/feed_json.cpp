#include "server/web/http/feed_json.h"

namespace fleetmap::web {
namespace {

nlohmann::json number_or_null(const std::optional<double>& v) { return v ? nlohmann::json(*v) : nlohmann::json(nullptr); }

nlohmann::json time_or_null(const std::string& sql_time) {
  return sql_time.empty() ? nlohmann::json(nullptr) : nlohmann::json(iso8601_from_utc_sql(sql_time));
}

}  // namespace

std::string iso8601_from_utc_sql(const std::string& sql_time) {
  if (sql_time.empty()) return sql_time;
  std::string out = sql_time;
  if (out.size() > 10 && out[10] == ' ') out[10] = 'T';
  return out + "Z";
}

nlohmann::json feed_robot_json(const RobotStatus& s, const std::optional<LonLat>& lonlat) {
  nlohmann::json task = nullptr;
  if (s.task_id && s.task_state) task = {{"id", *s.task_id}, {"state", std::string(to_string(*s.task_state))}};
  nlohmann::json goal = nullptr;
  if (s.goal_x && s.goal_y) goal = nlohmann::json::array({*s.goal_x, *s.goal_y});
  return {{"name", s.name},
          {"map", s.map.empty() ? nlohmann::json(nullptr) : nlohmann::json(s.map)},
          {"state", std::string(to_string(s.state))},
          {"x", number_or_null(s.x)},
          {"y", number_or_null(s.y)},
          {"theta", number_or_null(s.theta)},
          {"v", number_or_null(s.v)},
          {"lonlat", lonlat ? nlohmann::json::array({lonlat->lon, lonlat->lat}) : nlohmann::json(nullptr)},
          {"task", task},
          {"goal", goal},
          {"last_seen", time_or_null(s.last_seen)}};
}

nlohmann::json feed_task_json(const TaskInfo& t) {
  return {{"id", t.id},
          {"robot", t.robot},
          {"state", std::string(to_string(t.state))},
          {"goal", nlohmann::json::array({t.goal_x, t.goal_y})},
          {"created_at", time_or_null(t.created_at)},
          {"updated_at", time_or_null(t.updated_at)},
          {"reason", t.reason}};
}

}  // namespace fleetmap::web
