#pragma once
// The events of guided tours (seed 003 §III) as robots reported them with the TourEvent
// op (docs/protocol.md): table tour_events, sql/52_tour_events.sql. The server records
// them; 'fleetmap topo tour build' reads one robot's tour back, in the order the robot
// sent them, and builds the map's topological graph from it (common/planning/tour_builder.h).
//
//   TourStore(conn).record(robot_id, map_id, "", event, created_at);
//   std::vector<TourEvent> events = TourStore(conn).load(robot_id, "");
#include <optional>
#include <string>
#include <vector>

#include <mysql++/mysql++.h>

#include "common/planning/tour_event.h"

namespace fleetmap {

struct TourSummary {
  std::string tour;  // "" is the robot's default tour
  size_t events = 0;
  std::string first_at, last_at;
};

class TourStore {
 public:
  explicit TourStore(mysqlpp::Connection& c) : c_(c) {}

  // at: the request's time (rr.created_at), which becomes the event's t.
  void record(unsigned robot_id, std::optional<unsigned> map_id, const std::string& tour, const TourEvent& e,
              const std::string& at);
  // One robot's tour, in the order recorded; t in seconds since the epoch.
  std::vector<TourEvent> load(unsigned robot_id, const std::string& tour);
  // The robot's tours, by name.
  std::vector<TourSummary> tours(unsigned robot_id);

 private:
  mysqlpp::Connection& c_;
};

}  // namespace fleetmap
