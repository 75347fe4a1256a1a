#include "server/core/robot_partition.h"

#include <stdexcept>

namespace fleetmap {
namespace {

// A whole decimal number of at most 4 digits (kMaxPartitions), or nothing.
bool whole(const std::string& s, unsigned& out) {
  if (s.empty() || s.size() > 4) return false;
  out = 0;
  for (char c : s) {
    if (c < '0' || c > '9') return false;
    out = out * 10 + static_cast<unsigned>(c - '0');
  }
  return true;
}

}  // namespace

RobotPartition parse_robot_partition(const std::string& text) {
  const auto fail = [&](const std::string& why) {
    return std::invalid_argument("[server] partition: expected I/N with 0 <= I < N <= " + std::to_string(kMaxPartitions) +
                                 " (this server takes the robots whose id mod N is I), got '" + text + "'" + why);
  };
  const auto slash = text.find('/');
  if (slash == std::string::npos) throw fail("");
  RobotPartition p;
  if (!whole(text.substr(0, slash), p.index) || !whole(text.substr(slash + 1), p.count)) throw fail("");
  if (p.count == 0 || p.count > kMaxPartitions) throw fail(": N out of range");
  if (p.index >= p.count) throw fail(": I must be below N");
  return p;
}

}  // namespace fleetmap
