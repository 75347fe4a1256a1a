#pragma once
// The robot state and task objects of the WebSocket feed (docs/web-api.md), the same
// shape as GET /api/robots and GET /api/tasks give.
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "common/gis/geo_transform.h"
#include "protocol/fleet_store.h"

namespace fleetmap::web {

// "2026-12-02 04:10:08.123456" (a TIMESTAMP read in a UTC session) ->
// "2026-12-02T04:10:08.123456Z"; "" -> "".
std::string iso8601_from_utc_sql(const std::string& sql_time);

// {"name","map","state","x","y","theta","v","lonlat","task","goal","last_seen"}; times
// read in a UTC session; lonlat given when the robot's map is georeferenced.
nlohmann::json feed_robot_json(const RobotStatus& s, const std::optional<LonLat>& lonlat);

// {"id","robot","state","goal":[x,y],"created_at","updated_at","reason"}.
nlohmann::json feed_task_json(const TaskInfo& t);

}  // namespace fleetmap::web
