#pragma once
// A guide's tour as a file (fleetmap-robot --tour, docs/topology-tour.md): a JSON list of
// waypoints the guide walks in order; a waypoint with an "event" is where the guide tells
// the robot about a node (seed 003 §III), and the robot sends TourEvent when it gets there.
//
//   [{"x": -26.6, "y": 19.7, "event": "place", "name": "dock"},
//    {"x": -26.6, "y": 8.6, "event": "crossing"},
//    {"x": -20.0, "y": 8.6}, ...]
//
// "event": corridor, room, door, crossing or place (a place needs a "name").
#include <string>
#include <string_view>
#include <vector>

#include "common/core/error.h"
#include "common/planning/tour_plan.h"

namespace fleetmap {

// "file: [3].event: expected ..., got ..."
class TourFormatError : public FileFormatError {
 public:
  using FileFormatError::FileFormatError;
};

std::vector<TourWaypoint> read_tour_json(std::string_view text, const std::string& file = "<input>");
std::vector<TourWaypoint> read_tour_json_file(const std::string& path);  // also throws when unreadable
std::string write_tour_json(const std::vector<TourWaypoint>& tour);

}  // namespace fleetmap
