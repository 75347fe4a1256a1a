#include "common/planning/tour_event.h"

namespace fleetmap {

std::string_view to_string(TourEventKind k) {
  switch (k) {
    case TourEventKind::EnterCorridor: return "corridor";
    case TourEventKind::EnterRoom: return "room";
    case TourEventKind::Door: return "door";
    case TourEventKind::Crossing: return "crossing";
    case TourEventKind::Place: return "place";
  }
  return "?";
}

std::optional<TourEventKind> tour_event_kind_from_string(std::string_view s) {
  for (TourEventKind k : {TourEventKind::EnterCorridor, TourEventKind::EnterRoom, TourEventKind::Door,
                          TourEventKind::Crossing, TourEventKind::Place})
    if (to_string(k) == s) return k;
  return std::nullopt;
}

std::optional<EdgeType> next_edge_type(TourEventKind k) {
  switch (k) {
    case TourEventKind::EnterCorridor: return EdgeType::Corridor;
    case TourEventKind::EnterRoom: return EdgeType::Room;
    case TourEventKind::Door: return EdgeType::Door;
    case TourEventKind::Crossing:
    case TourEventKind::Place: return std::nullopt;
  }
  return std::nullopt;
}

}  // namespace fleetmap
