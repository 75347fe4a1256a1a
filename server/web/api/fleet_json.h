#pragma once
// The robot state and task objects of the API, the same in REST answers (GET /api/robots,
// GET /api/tasks) and in the WebSocket feed's "robots" and "tasks" messages
// (docs/web-api.md):
//
//   robot: {"name","map","state","x","y","theta","v","lonlat":[lon,lat]|null,
//           "task":{"id","state"}|null,"goal":[x,y]|null,"last_seen":ISO 8601 UTC|null}
//   task:  {"id","robot","state","goal":[x,y],"created_at","updated_at","reason"}
//
// state is RobotState's / TaskState's word (protocol/fleet_states.h); numbers unknown are
// null; lonlat only when the robot's map is georeferenced and its pose known; task and
// goal are the robot's latest task's (the one `fleetmap robots` shows).
#include <map>
#include <optional>
#include <string>

#include <mysql++/mysql++.h>
#include <nlohmann/json.hpp>

#include "common/gis/geo_transform.h"
#include "common/io/output_frame.h"
#include "protocol/fleet_store.h"

namespace fleetmap::web {

// The WGS 84 frame of every georeferenced map, by name (maps whose georeference PROJ
// cannot use are left out: their robots get "lonlat": null).
std::map<std::string, OutputFrame> wgs84_frames(mysqlpp::Connection& c);

// s read under UtcSession (its last_seen in UTC); lonlat from the map's WGS 84 frame
// (nullptr: not georeferenced), or given (the feed keeps one GeoTransform per map).
nlohmann::json robot_state_json(const RobotStatus& s, const OutputFrame* wgs84);
nlohmann::json robot_state_json(const RobotStatus& s, const std::optional<LonLat>& lonlat);
nlohmann::json task_json(const TaskInfo& t);  // t read under UtcSession

// Every robot's state (an array, by name), read on c with times in UTC.
nlohmann::json read_robot_states(mysqlpp::Connection& c);
// One robot's state; throws RobotNotFound.
nlohmann::json read_robot_state(mysqlpp::Connection& c, const std::string& robot);
// Tasks newest first (only robot's when given), at most limit, read on c with times in UTC.
nlohmann::json read_tasks(mysqlpp::Connection& c, const std::optional<std::string>& robot, size_t limit);

}  // namespace fleetmap::web
