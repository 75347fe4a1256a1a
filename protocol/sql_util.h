#pragma once
// Small conversions between MySQL++ rows and C++ values, shared by the table classes.
#include <charconv>
#include <optional>
#include <string>

#include <mysql++/mysql++.h>

#include "protocol/connection.h"
#include "protocol/fleet_states.h"
#include "protocol/task_lifecycle.h"

namespace fleetmap::sql {

inline double to_double(const mysqlpp::String& s) {
  double v = 0;
  auto [end, ec] = std::from_chars(s.data(), s.data() + s.length(), v);
  if (ec != std::errc() || end != s.data() + s.length()) throw DbError("unexpected number from the database: '" + std::string(s) + "'");
  return v;
}

inline long long to_int(const mysqlpp::String& s) {
  long long v = 0;
  auto [end, ec] = std::from_chars(s.data(), s.data() + s.length(), v);
  if (ec != std::errc() || end != s.data() + s.length()) throw DbError("unexpected integer from the database: '" + std::string(s) + "'");
  return v;
}

inline unsigned long long to_uint(const mysqlpp::String& s) {
  unsigned long long v = 0;
  auto [end, ec] = std::from_chars(s.data(), s.data() + s.length(), v);
  if (ec != std::errc() || end != s.data() + s.length()) throw DbError("unexpected integer from the database: '" + std::string(s) + "'");
  return v;
}

inline std::string to_string(const mysqlpp::String& s) { return std::string(s.data(), s.length()); }

inline std::optional<double> opt_double(const mysqlpp::String& s) {
  if (s.is_null()) return std::nullopt;
  return to_double(s);
}

inline std::optional<long long> opt_int(const mysqlpp::String& s) {
  if (s.is_null()) return std::nullopt;
  return to_int(s);
}

// A state as an SQL literal: 'lost'.
inline std::string quoted(RobotState s) { return "'" + std::string(fleetmap::to_string(s)) + "'"; }
inline std::string quoted(TaskState s) { return "'" + std::string(fleetmap::to_string(s)) + "'"; }

// The open task states as an SQL list, for tasks.state IN ...: ('assigned', 'acknowledged', 'active').
inline const std::string& open_task_states() {
  static const std::string list = [] {
    std::string s;
    for (TaskState t : kTaskStates)
      if (is_open(t)) s += (s.empty() ? "(" : ", ") + quoted(t);
    return s + ")";
  }();
  return list;
}

// A server's share of the robots (server/core/robot_partition.h): " AND <robot_id> % N = I",
// nothing when one server takes them all (N <= 1), so the single-server queries stay as
// they were.
inline std::string share_condition(const char* robot_id, unsigned modulus, unsigned remainder) {
  if (modulus <= 1) return "";
  return std::string(" AND ") + robot_id + " % " + std::to_string(modulus) + " = " + std::to_string(remainder);
}

}  // namespace fleetmap::sql
