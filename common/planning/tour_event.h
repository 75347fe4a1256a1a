#pragma once
// What the guide of a tour tells the robot (seed 003 §III): "every time when they leave a
// room or a corridor, and then again, when a new room or corridor is entered. Also
// corridor crossings and other points of interest". Each event is a node of the
// topological map to be and, as in the seed ("each time the guide tells the robot about a
// new node, it also announces the type of the next edge"), the type of the edge that
// leaves it: EnterCorridor -> corridor, EnterRoom -> room, Door -> door (the edge through
// the doorway); Crossing and Place keep the type of the edge they lie on.
//
//   TourEvent e{.kind = TourEventKind::Door, .pose = {3.1, 0.2, M_PI / 2}, .t = 12.5};
#include <optional>
#include <string>
#include <string_view>

#include "common/planning/topo_graph.h"

namespace fleetmap {

enum class TourEventKind { EnterCorridor, EnterRoom, Door, Crossing, Place };

// The protocol's and files' words: "corridor", "room", "door", "crossing", "place".
std::string_view to_string(TourEventKind k);
std::optional<TourEventKind> tour_event_kind_from_string(std::string_view s);

// The type of the edge an event of this kind starts, or nullopt: keeps the current one.
std::optional<EdgeType> next_edge_type(TourEventKind k);

struct TourPose {
  double x = 0, y = 0;  // map frame, metres
  double theta = 0;     // heading, radians from +x counter-clockwise
  friend bool operator==(const TourPose&, const TourPose&) = default;
};

struct TourEvent {
  TourEventKind kind = TourEventKind::EnterCorridor;
  TourPose pose;     // the robot's pose when it was told
  std::string name;  // a Place has one ("charging station"); optional for the others
  double t = 0;      // seconds, any epoch; events are used in the order given
  friend bool operator==(const TourEvent&, const TourEvent&) = default;
};

}  // namespace fleetmap
