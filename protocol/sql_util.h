#pragma once
// Small conversions between MySQL++ rows and C++ values, shared by the table classes.
#include <charconv>
#include <optional>
#include <string>

#include <mysql++/mysql++.h>

#include "protocol/connection.h"

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

}  // namespace fleetmap::sql
