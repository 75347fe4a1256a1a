#pragma once
// Which robots one fleetmap-server serves when several share the fleet: "I/N" takes the
// robots whose id mod N is I. On a Galera cluster two servers claiming the same robot on
// different nodes both succeed locally (FOR UPDATE SKIP LOCKED is per node) and one
// commit fails certification; disjoint shares never meet (docs/galera.md).
#include <string>

namespace fleetmap {

struct RobotPartition {
  unsigned index = 0;  // I
  unsigned count = 1;  // N; 1: every robot (the default, one server)

  bool all() const { return count == 1; }
  bool owns(unsigned robot_id) const { return robot_id % count == index; }
  std::string text() const { return std::to_string(index) + "/" + std::to_string(count); }
};

// "I/N" with 0 <= I < N <= kMaxPartitions; throws std::invalid_argument naming the
// expected form.
RobotPartition parse_robot_partition(const std::string& text);
constexpr unsigned kMaxPartitions = 1024;

}  // namespace fleetmap
