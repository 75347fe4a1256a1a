#pragma once
// Shortest decimal text that reads back to the same double (canonical map files).
#include <charconv>
#include <string>

namespace fleetmap {

inline std::string format_number(double v) {
  char buf[32];
  auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
  (void)ec;  // 32 bytes always hold the shortest form of a double
  return std::string(buf, end);
}

}  // namespace fleetmap
