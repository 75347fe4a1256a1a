#include "client/sim/laser_simulator.h"

#include <algorithm>
#include <cmath>

namespace fleetmap::localization {

namespace {
constexpr double kWallMargin = 0.05;  // metres left between a person and a wall
constexpr int kClearanceRays = 32;    // rays that check a disc is clear of walls
constexpr int kPlaceAttempts = 20;

// Range along unit direction dir from o to the disc (centre c, radius r), or +inf.
double ray_disc(Point o, Point dir, Point c, double r) {
  const Point oc = c - o;
  const double t = dot(oc, dir);
  const double perp_sq = dot(oc, oc) - t * t;
  if (t <= 0 || perp_sq > r * r) return INFINITY;
  return std::max(0.0, t - std::sqrt(r * r - perp_sq));
}
}  // namespace

LaserSimulator::LaserSimulator(std::shared_ptr<const RayCaster> world, LaserSimulatorOptions options, uint64_t seed)
    : world_(std::move(world)), options_(options), beams_(evenly_spread_angles(options.beams, options.fov)), rng_(seed) {}

std::vector<double> LaserSimulator::true_scan(const Pose& truth) const {
  std::vector<double> r(beams_.size());
  world_->cast_scan(truth.point(), truth.theta, beams_, r.data());
  return r;
}

bool LaserSimulator::clear_of_walls(Point c, double radius) const {
  // Rays from the centre miss a wall's end that points at it between two rays, so the
  // sides of a polygon around the disc are cast too: a wall that enters the disc crosses
  // one of them, unless it lies wholly inside, where the centre's rays meet it.
  const double clear = radius + kWallMargin;
  const double corner = clear / std::cos(kPi / kClearanceRays);  // the polygon holds the disc
  const double side = 2 * corner * std::sin(kPi / kClearanceRays);
  for (int k = 0; k < kClearanceRays; ++k) {
    const double a = 2 * kPi * k / kClearanceRays, b = 2 * kPi * (k + 1) / kClearanceRays;
    if (world_->cast(c, a) < clear) return false;
    if (world_->cast(c + corner * ray_direction(a), (a + b) / 2 + kPi / 2) < side) return false;
  }
  return true;
}

bool LaserSimulator::clear_of_people(Point c, double radius, const Person* self) const {
  for (const Person& q : people_)
    if (&q != self && q.radius > 0 && distance(c, q.centre) < radius + q.radius) return false;
  return true;
}

double LaserSimulator::field() const {
  return options_.people_field > 0 ? std::min(options_.people_field, 2 * kPi) : options_.fov;
}

size_t LaserSimulator::people_in_view(const Pose& truth) const {
  return static_cast<size_t>(
      std::count_if(people_.begin(), people_.end(), [&](const Person& p) { return within(truth, p, options_.fov); }));
}

bool LaserSimulator::within(const Pose& truth, const Person& p, double field) const {
  if (!(p.radius > 0)) return false;
  const Point oc = p.centre - truth.point();
  const double d = norm(oc);
  const double bearing = std::atan2(oc.y, oc.x);
  if (std::fabs(angle_diff(bearing, truth.theta)) > field / 2) return false;
  if (d - p.radius < options_.min_person_range || d + p.radius > rmax()) return false;
  return world_->cast(truth.point(), bearing) >= d;  // its centre in line of sight
}

bool LaserSimulator::place_in_field(const Pose& truth, Person& p) {
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  for (int a = 0; a < kPlaceAttempts; ++a) {
    const double radius = (options_.person_width + (2 * u01(rng_) - 1) * options_.person_width_spread) / 2;
    const double bearing = truth.theta + (u01(rng_) - 0.5) * field();
    const double wall = world_->cast(truth.point(), bearing);
    const double lo = options_.min_person_range + radius, hi = std::min(wall, rmax()) - radius - kWallMargin;
    if (!(radius > 0) || hi <= lo) continue;
    const Point c = truth.point() + (lo + u01(rng_) * (hi - lo)) * ray_direction(bearing);
    if (!clear_of_walls(c, radius) || !clear_of_people(c, radius, &p)) continue;
    p.centre = c;
    p.radius = radius;
    p.velocity = options_.person_speed * ray_direction(2 * kPi * u01(rng_));
    return true;
  }
  p.radius = 0;  // nowhere to stand in the field now (the laser against a wall): try next scan
  return false;
}

void LaserSimulator::walk(const Pose& truth, Person& p) {
  const double step = options_.person_speed * options_.scan_period;
  if (!(p.radius > 0) || !(step > 0)) return;
  const Point next = p.centre + options_.scan_period * p.velocity;
  const double heading = std::atan2(p.velocity.y, p.velocity.x);
  const bool blocked = world_->cast(p.centre, heading) < step + p.radius + kWallMargin ||
                       distance(next, truth.point()) < options_.min_person_range + p.radius ||
                       !clear_of_walls(next, p.radius) || !clear_of_people(next, p.radius, &p);
  if (!blocked) {
    p.centre = next;
    return;
  }
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  p.velocity = options_.person_speed * ray_direction(2 * kPi * u01(rng_));  // turn, stay this scan
}

std::vector<double> LaserSimulator::scan(const Pose& truth) {
  std::vector<double> r = true_scan(truth);
  if (options_.people > 0) {
    if (people_.empty()) {
      Person unplaced;
      unplaced.radius = 0;  // in no one's way until placed
      people_.assign(static_cast<size_t>(options_.people), unplaced);
      for (Person& p : people_) place_in_field(truth, p);
    } else {
      for (Person& p : people_) {
        walk(truth, p);
        if (!within(truth, p, field())) place_in_field(truth, p);
      }
    }
    std::vector<Point> dirs(beams_.size());
    scan_directions(truth.theta, beams_, dirs.data());
    for (const Person& p : people_) {
      if (!(p.radius > 0)) continue;
      for (size_t j = 0; j < r.size(); ++j) r[j] = std::min(r[j], ray_disc(truth.point(), dirs[j], p.centre, p.radius));
    }
  }
  const double rmax = this->rmax();
  std::normal_distribution<double> noise(0.0, options_.sigma);
  for (double& v : r)
    if (v < rmax) v = std::clamp(v + noise(rng_), 0.0, rmax);
  return r;
}

}  // namespace fleetmap::localization
