#include "client/sim/guided_walk.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace fleetmap {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kReached = 0.1;  // metres: this close is there

}  // namespace

GuidedWalk::GuidedWalk(std::vector<TourWaypoint> tour, GuidedWalkOptions o)
    : tour_(std::move(tour)), o_(o), drive_({}, OdometryNoise{0, 0, 0}, 1) {
  if (tour_.empty()) throw std::invalid_argument("a guided walk needs at least one waypoint");
  cum_.push_back(0);
  for (size_t i = 1; i < tour_.size(); ++i) cum_.push_back(cum_.back() + distance(tour_[i - 1].p, tour_[i].p));
  drive_.stop_at({tour_[0].p.x, tour_[0].p.y, heading_at(0)});
  while (next_event_ < tour_.size() && !tour_[next_event_].event) ++next_event_;
  closest_ = kInf;
}

Point GuidedWalk::at(double s) const {
  s = std::clamp(s, 0.0, cum_.back());
  const size_t i = static_cast<size_t>(std::upper_bound(cum_.begin(), cum_.end(), s) - cum_.begin());
  if (i >= cum_.size()) return tour_.back().p;
  const double len = cum_[i] - cum_[i - 1];
  const double f = len > 0 ? (s - cum_[i - 1]) / len : 0;
  return tour_[i - 1].p + f * (tour_[i].p - tour_[i - 1].p);
}

double GuidedWalk::heading_at(double s) const {
  const Point a = at(s), b = at(s + 0.5);
  if (distance(a, b) < 1e-9) return drive_.pose().theta;
  return std::atan2(b.y - a.y, b.x - a.x);
}

std::vector<TourEvent> GuidedWalk::step() {
  std::vector<TourEvent> out;
  if (done()) return out;
  const double dt = o_.step_s;
  time_s_ += dt;
  const Point r = robot().point();
  // The carrot runs ahead of the robot along the trail, never past the guide's heels
  // (the whole trail once the guide is at its end: the guide steps aside).
  // It also waits on the next event point until the robot has been there, so that the
  // robot reaches every point the guide told it about (a dead end's too).
  const bool guide_at_end = guide_s_ >= cum_.back();
  double carrot_limit = guide_at_end ? cum_.back() : std::max(0.0, guide_s_ - o_.follow_distance);
  if (next_event_ < tour_.size()) carrot_limit = std::min(carrot_limit, cum_[next_event_]);
  while (carrot_s_ < carrot_limit && distance(r, at(carrot_s_)) < o_.lookahead)
    carrot_s_ = std::min(carrot_limit, carrot_s_ + 0.02);
  // The guide walks on unless the robot lags behind.
  if (guide_s_ - carrot_s_ < o_.wait_distance) guide_s_ = std::min(cum_.back(), guide_s_ + o_.guide_speed * dt);

  const Point target = at(carrot_s_);
  const double d = distance(r, target);
  double v = 0, w = 0;
  if (d > 0.05) {
    const double alpha = localization::angle_diff(std::atan2(target.y - r.y, target.x - r.x), robot().theta);
    v = std::abs(alpha) > M_PI / 3 ? 0 : std::min(o_.max_speed, d / dt);
    w = v > 0 ? 2 * v * std::sin(alpha) / std::max(d, 1e-6) : std::copysign(o_.max_turn_rate, alpha);
    w = std::clamp(w, -o_.max_turn_rate, o_.max_turn_rate);
    v = std::min(v, d / dt);
  }
  drive_.step(v, w, dt);

  // The next event point: reported at the robot's closest approach to it.
  while (next_event_ < tour_.size()) {
    const TourWaypoint& wp = tour_[next_event_];
    const double dist = distance(robot().point(), wp.p);
    if (dist < closest_) closest_ = dist, closest_pose_ = robot(), closest_t_ = time_s_;
    if (closest_ > kReached) break;
    out.push_back({*wp.event, {closest_pose_.x, closest_pose_.y, closest_pose_.theta}, wp.name, closest_t_});
    ++next_event_;
    while (next_event_ < tour_.size() && !tour_[next_event_].event) ++next_event_;
    closest_ = kInf;
  }
  return out;
}

bool GuidedWalk::done() const {
  return time_s_ >= o_.max_time_s || (next_event_ >= tour_.size() && carrot_s_ >= cum_.back() &&
                                      distance(robot().point(), tour_.back().p) < 0.2);
}

}  // namespace fleetmap
