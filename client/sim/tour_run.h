#pragma once
// fleetmap-robot --tour (docs/topology-tour.md): the simulated guided walk
// (guided_walk.h) spoken over RR/SA. The robot reports SendPos at report_every_s while
// it follows the guide, and at each point the guide told it about a SendPos of that pose
// and a TourEvent without a pose (the server stamps the last SendPos), waiting for its
// OpAck. The poses are the walk's own (the guide's trail is the ground truth; no
// localization runs on a tour).
#include <atomic>
#include <string>
#include <vector>

#include "client/robot_client.h"
#include "client/sim/guided_walk.h"
#include "common/planning/tour_plan.h"

namespace fleetmap {

struct TourRunOptions {
  GuidedWalkOptions walk;
  std::string tour;               // TourEvent params.tour ("" : the robot's default tour)
  double report_every_s = 1.0 / 3;
  bool realtime = true;           // keep pace with the wall clock
};

// Returns the number of events the server acknowledged. Throws RobotClientError when
// the server answers a TourEvent with an Error.
size_t run_guided_tour(RobotClient& client, const std::vector<TourWaypoint>& tour, const TourRunOptions& o,
                       const std::atomic<bool>& stop);

}  // namespace fleetmap
