#include "client/sim/tour_run.h"

#include <chrono>
#include <thread>

#include <spdlog/spdlog.h>

namespace fleetmap {
namespace {

Json pose_params(const Pose& p, double v) { return {{"x", p.x}, {"y", p.y}, {"theta", p.theta}, {"v", v}}; }

}  // namespace

size_t run_guided_tour(RobotClient& client, const std::vector<TourWaypoint>& tour, const TourRunOptions& o,
                       const std::atomic<bool>& stop) {
  GuidedWalk walk(tour, o.walk);
  size_t acknowledged = 0;
  double next_report = 0;
  Pose last = walk.robot();
  auto clock = std::chrono::steady_clock::now();
  while (!walk.done() && !stop) {
    const std::vector<TourEvent> events = walk.step();
    const Pose& p = walk.robot();
    const double v = distance(p.point(), last.point()) / o.walk.step_s;
    last = p;
    if (walk.time_s() >= next_report) {
      client.send(RequestOp::SendPos, pose_params(p, v));
      next_report += o.report_every_s;
    }
    for (const TourEvent& e : events) {
      client.send(RequestOp::SendPos, pose_params({e.pose.x, e.pose.y, e.pose.theta}, v));
      Json params = {{"event", std::string(to_string(e.kind))}};
      if (!e.name.empty()) params["name"] = e.name;
      if (!o.tour.empty()) params["tour"] = o.tour;
      const auto id = client.send(RequestOp::TourEvent, params);
      const auto answers = client.await(id, 1);
      if (answers.at(0).op != "OpAck")
        throw RobotClientError("TourEvent " + params.dump() + " answered " + answers[0].op + " " +
                               answers[0].params.dump());
      ++acknowledged;
      spdlog::info("tour: {} at ({:.2f}, {:.2f}) after {:.0f} s", to_string(e.kind), e.pose.x, e.pose.y, e.t);
    }
    if (o.realtime) {
      clock += std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(o.walk.step_s));
      std::this_thread::sleep_until(clock);
    }
  }
  client.send(RequestOp::SendPos, pose_params(walk.robot(), 0));
  client.send(RequestOp::Stopped);
  return acknowledged;
}

}  // namespace fleetmap
