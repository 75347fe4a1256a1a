#include "client/sim/sim_robot.h"

#include <stdexcept>
#include <thread>

#include <spdlog/spdlog.h>

#include "common/raycast/sweep_ray_caster.h"
#include "client/localization/report_gate.h"
#include "client/sim/localization_trials.h"
#include "protocol/map_codec.h"

namespace fleetmap {

namespace loc = localization;

constexpr double kBumperDistance = 0.15;  // metres from the laser's origin to the front

SimRobot::SimRobot(RobotClient& client, const Map& world, Pose start, const Map& first_map, SimRobotOptions o)
    : client_(client),
      o_(o),
      world_(make_fast_ray_caster(world, RayCasterOptions{o.laser_height, 15.0})),
      drive_(start, o.odometry, o.seed),
      laser_(world_, o.laser, o.seed + 1),
      lost_(o.lost),
      pursuit_(o.pursuit),
      rng_(o.seed + 2),
      map_(first_map) {
  // A preset that localizes on the real maps (bench-localization, docs/localization.md).
  const std::optional<loc::ParticleFilterOptions> preset = loc::preset(o.localizer);
  if (!preset || !preset->global_search)
    throw std::invalid_argument("SimRobotOptions.localizer: expected search or fast, got " + o.localizer);
  loc::ParticleFilterOptions fo = *preset;
  fo.particles = o.global_particles;
  fo.beams = o.laser.beams;
  fo.fov = o.laser.fov;
  fo.laser = {o.laser_height, 15.0};
  fo.seed = o.seed + 3;
  global_options_ = fo;
  filter_ = std::make_unique<loc::ParticleFilter>(first_map, fo);
  if (o.zoom) zoom_ = std::make_unique<ZoomMapClient>(client_, o.zoom_options);
}

double SimRobot::compass() {
  std::normal_distribution<double> n(0, loc::deg2rad(o_.compass_sigma_deg));
  return loc::normalize_angle(drive_.pose().theta + n(rng_));
}

std::optional<int> SimRobot::localize(int max_updates) {
  if (tracking_) {  // a tracking filter has few particles: global localization gets its own
    filter_ = std::make_unique<loc::ParticleFilter>(map_, global_options_);
    tracking_ = false;
  }
  filter_->init_global(compass());
  bool was_ambiguous = false;
  loc::ReportGate gate;
  for (int i = 1; i <= max_updates; ++i) {
    // Look around: turn 60 degrees in place (at 0.5 rad/s) between scans, so that six
    // turns show the filter the whole circle (ParticleFilterOptions::look_around_searches).
    const double turn = loc::deg2rad(60.0), rate = 0.5;
    const Odometry odo = drive_.step(0, rate, turn / rate);
    filter_->predict(odo);
    filter_->update(laser_.scan(drive_.pose()), compass());
    // Nothing to report before the look around's search, nor before the cloud converges
    // (the verdict below costs refinements).
    const loc::PoseEstimate e = filter_->estimate();
    const bool converged = !filter_->awaiting_search() && e.converged;
    // Look-alike places (identical rooms, a row of identical doors): say so and keep
    // localizing rather than report one of them as the pose.
    const loc::Ambiguity a = converged ? filter_->ambiguity() : loc::Ambiguity{};
    if (a.ambiguous() && !was_ambiguous)
      spdlog::warn("localizing: ambiguous, {} places look alike, the heaviest ({:.2f}, {:.2f}) with {:.0f} % of the "
                   "weight, the next ({:.2f}, {:.2f}) with {:.0f} %; not reporting a pose",
                   a.places.size(), a.places[0].x, a.places[0].y, 100 * a.weights[0], a.places[1].x, a.places[1].y,
                   100 * a.weights[1]);
    was_ambiguous = was_ambiguous || a.ambiguous();
    // Converged and alone, on the gate's scans in a row (report_gate.h).
    if (!gate.update(converged && !a.ambiguous())) continue;
    spdlog::info("localized after {} updates at ({:.2f}, {:.2f}, {:.1f} deg); truth ({:.2f}, {:.2f}, {:.1f} deg)", i,
                 e.pose.x, e.pose.y, loc::rad2deg(e.pose.theta), drive_.pose().x, drive_.pose().y,
                 loc::rad2deg(drive_.pose().theta));
    start_tracking(e.pose, std::max(0.05, e.spread_xy), std::max(0.01, e.spread_theta));
    return i;
  }
  spdlog::warn("global localization did not converge in {} updates{}", max_updates,
               was_ambiguous ? " (ambiguous: places look alike)" : "");
  return std::nullopt;
}

void SimRobot::start_tracking(const Pose& pose, double sd_xy, double sd_theta) {
  // Tracking: fewer particles, their count adapted by KLD sampling.
  loc::ParticleFilterOptions fo = filter_->options();
  fo.adaptive = true;
  fo.particles = o_.tracking_particles;
  fo.kld.max_particles = o_.tracking_particles;
  fo.kld.min_particles = std::min<size_t>(fo.kld.min_particles, o_.tracking_particles);
  filter_ = std::make_unique<loc::ParticleFilter>(map_, fo);
  filter_->init_pose(pose, sd_xy, sd_theta);
  tracking_ = true;
  localizing_ = false;
  lost_.reset();
  // A few scans standing still settle the cloud on the map.
  for (int i = 0; i < 3; ++i) filter_->update(laser_.scan(drive_.pose()), compass());
}

void SimRobot::filter_step(const Odometry& odo) {
  filter_->predict(odo);
  const std::vector<double> scan = laser_.scan(drive_.pose());
  filter_->update(scan, compass());
  if (!tracking_) return;
  const loc::PoseEstimate e = filter_->estimate();
  if (lost_.update(loc::scan_evidence(filter_->ray_caster(), e.pose, filter_->beam_angles(), scan, lost_.options()),
                   odo))
    relocalize();
}

void SimRobot::relocalize() {
  const loc::PoseEstimate e = filter_->estimate();
  spdlog::warn("lost: the scans no longer fit the estimate ({:.2f}, {:.2f}, {:.1f} deg; fit {:.2f}, usually {:.2f}); "
               "truth ({:.2f}, {:.2f}); stopping to localize again",
               e.pose.x, e.pose.y, loc::rad2deg(e.pose.theta), lost_.fast(), lost_.slow(), drive_.pose().x,
               drive_.pose().y);
  ++relocalizations_;
  localizing_ = true;
  pursuit_.clear();
  goal_.reset();
  path_request_.reset();
  moving_ = false;
  // The server fails the task and shows the robot localizing (docs/protocol.md).
  client_.send(RequestOp::SendPos, Json{{"status", "lost"}, {"v", 0}});
  if (localize()) report_pose(0, 0);
}

void SimRobot::report_pose(double v, double w) {
  if (localizing_) return;  // no pose to report: the server was told (relocalize)
  const loc::PoseEstimate now = filter_->estimate();
  client_.send(RequestOp::SendPos, Json{{"x", now.pose.x}, {"y", now.pose.y}, {"theta", now.pose.theta}, {"v", v}, {"w", w}});
  if (zoom_) zoom_->update(now.pose.point(), time_s_);
}

void SimRobot::stopped() {
  moving_ = false;
  client_.send(RequestOp::Stopped);
}

void SimRobot::handle(const ReceivedAnswer& a) {
  if (zoom_ && zoom_->on_answer(a, time_s_)) {
    map_ = *zoom_->window();
    filter_->set_map(map_);
    spdlog::info("new map window around ({:.1f}, {:.1f}): {} segments", zoom_->zoom().centre()->x,
                 zoom_->zoom().centre()->y, zoom_->window()->segment_count());
    return;
  }
  if (a.op == "SetPosEnd") {
    const SetPoseParams p = decode_set_pose(a.params);
    goal_ = Point{p.x, p.y};
    pose_resent_ = false;
    spdlog::info("goal ({:.2f}, {:.2f}); asking for a path", p.x, p.y);
    path_request_ = client_.send(RequestOp::GetPath);
  } else if (a.op == "SetPath" && a.request_id == path_request_) {
    const SetPathParams p = decode_set_path(a.params);
    spdlog::info("path of {} waypoints, {:.1f} m", p.waypoints.size(), p.length);
    pursuit_.set_path(p.waypoints);
    route_ = RouteEdges(p);
    if (!route_.empty()) spdlog::info("route through {} graph nodes, {} edges", p.nodes.size(), p.edges.size());
    moving_ = true;
    path_request_.reset();
  } else if (a.op == "Error" && a.request_id == path_request_ && goal_ && a.params.value("code", "") == "no_pose" &&
             !pose_resent_) {
    // The goal came before the server had its first SendPos: report the pose, ask again
    // (the server serves a robot's requests in order).
    pose_resent_ = true;
    report_pose(0, 0);
    path_request_ = client_.send(RequestOp::GetPath);
  } else if (a.op == "Error" && a.request_id == path_request_ && goal_) {
    // No path (the server failed the task) or no planner: a straight line would drive
    // into whatever is in the way, so the robot stays where it is and says so (Stopped).
    spdlog::warn("GetPath refused ({}): {}; goal ({:.2f}, {:.2f}) dropped, stopping", a.params.value("code", "?"),
                 a.params.value("message", ""), goal_->x, goal_->y);
    pursuit_.clear();
    goal_.reset();
    path_request_.reset();
    ++goals_refused_;
    stopped();
  } else if (a.op == "Abort") {
    spdlog::warn("abort: {}", a.params.value("reason", ""));
    pursuit_.clear();
    route_ = RouteEdges();
    goal_.reset();
    stopped();
  } else if (a.op == "Error") {
    spdlog::warn("server error: {}", a.params.dump());
  }
}

void SimRobot::run(const std::atomic<bool>& stop, double duration_s) {
  Odometry since_update{};
  double next_scan = 0, next_report = 0;
  const auto wall0 = std::chrono::steady_clock::now();
  while (!stop && time_s_ < duration_s) {
    for (const ReceivedAnswer& a : client_.receive()) handle(a);
    const loc::PoseEstimate e = filter_->estimate();
    const Command c = moving_ ? pursuit_.command(e.pose) : Command{0, 0, false};
    // The hook for per-edge behaviour (seed 003 §II-B): a real robot switches its
    // controller (corridor following, door passing); the simulated one says so.
    if (moving_)
      if (const std::optional<size_t> k = route_.update(e.pose.point())) {
        const PathEdge& edge = route_.edge(*k);
        spdlog::info("on a {} edge, node {} -> {}", edge.type, edge.from, edge.to);
      }
    if (moving_ && c.arrived) {
      spdlog::info("arrived at ({:.2f}, {:.2f}); truth ({:.2f}, {:.2f})", e.pose.x, e.pose.y, drive_.pose().x,
                   drive_.pose().y);
      ++goals_reached_;
      goal_.reset();
      stopped();
    }
    // The true robot cannot drive through a wall: its bumper stops it (the estimate may
    // be wrong, the world is not).
    double v = c.v;
    if (v != 0) {
      const Pose& t = drive_.pose();
      const double heading = v > 0 ? t.theta : t.theta + M_PI;
      if (world_->cast(t.point(), heading) < std::abs(v) * o_.step_s + kBumperDistance) {
        if (!bumped_) spdlog::warn("bumped into a wall at ({:.2f}, {:.2f})", t.x, t.y);
        bumped_ = true;
        v = 0;
      } else {
        bumped_ = false;
      }
    }
    const Odometry odo = drive_.step(v, c.w, o_.step_s);
    if (o_.kidnap_at_s && time_s_ < *o_.kidnap_at_s && time_s_ + o_.step_s >= *o_.kidnap_at_s) {
      spdlog::warn("kidnapped: moved from ({:.2f}, {:.2f}) to ({:.2f}, {:.2f}) without odometry", drive_.pose().x,
                   drive_.pose().y, o_.kidnap_to.x, o_.kidnap_to.y);
      drive_.stop_at(o_.kidnap_to);
    }
    // Lost and not found by the last try: look around again.
    if (localizing_ && localize()) report_pose(0, 0);
    // Compose the increments since the last filter update (robot frame at that update).
    const double ct = std::cos(since_update.dtheta), st = std::sin(since_update.dtheta);
    since_update = {since_update.dx + ct * odo.dx - st * odo.dy, since_update.dy + st * odo.dx + ct * odo.dy,
                    loc::normalize_angle(since_update.dtheta + odo.dtheta)};
    time_s_ += o_.step_s;
    if (time_s_ >= next_scan && (c.v != 0 || c.w != 0)) {
      filter_step(since_update);
      since_update = {};
      next_scan = time_s_ + o_.scan_every_s;
    }
    if (time_s_ >= next_report) {
      report_pose(c.v, c.w);
      next_report = time_s_ + o_.report_every_s;
    }
    if (o_.realtime) {
      const auto due = wall0 + std::chrono::duration<double>(time_s_);
      std::this_thread::sleep_until(due);
    }
  }
}

}  // namespace fleetmap
