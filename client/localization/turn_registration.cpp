#include "client/localization/turn_registration.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fleetmap::localization {

namespace {

// before's range along angle a of its frame; NaN outside its field of view or where
// the neighbouring beams did not both hit.
double range_along(const std::vector<double>& ranges, const std::vector<double>& beams, double rmax, double a,
                   double jump) {
  if (a < beams.front() || a > beams.back()) return std::numeric_limits<double>::quiet_NaN();
  const size_t hi = std::clamp<size_t>(std::lower_bound(beams.begin(), beams.end(), a) - beams.begin(), 1,
                                       beams.size() - 1);
  const size_t lo = hi - 1;
  const double r0 = ranges[lo], r1 = ranges[hi];
  const double t = (a - beams[lo]) / (beams[hi] - beams[lo]);
  if (!(r0 < rmax) || !(r1 < rmax)) {
    const double nearest = t < 0.5 ? r0 : r1;
    return nearest < rmax ? nearest : std::numeric_limits<double>::quiet_NaN();
  }
  if (std::fabs(r1 - r0) > jump) return t < 0.5 ? r0 : r1;
  return r0 + t * (r1 - r0);
}

}  // namespace

double register_turn(const std::vector<double>& before, const std::vector<double>& after,
                     const std::vector<double>& beams, double rmax, double odometry_turn, double odometry_sd,
                     const TurnRegistrationOptions& o) {
  if (beams.size() < 2 || before.size() != beams.size() || after.size() != beams.size()) return odometry_turn;
  const double prior_var = std::max(odometry_sd * odometry_sd, 1e-12);
  const double cap2 = o.cap * o.cap, var2 = 2 * o.sigma * o.sigma;
  // The mean term per overlapping beam, so that a turn is not preferred for overlapping
  // less; weighed as if every beam of `after` that hit overlapped.
  const double hits = static_cast<double>(std::count_if(after.begin(), after.end(), [&](double r) { return r < rmax; }));
  double best = odometry_turn, best_cost = std::numeric_limits<double>::infinity();
  const int steps = static_cast<int>(std::ceil(o.window / o.step));
  for (int s = -steps; s <= steps; ++s) {
    const double turn = odometry_turn + s * o.step;
    double sum = 0;
    int overlap = 0;
    for (size_t j = 0; j < beams.size(); ++j) {
      if (!(after[j] < rmax)) continue;
      // after's beam j points along beams[j] + turn in before's frame.
      const double r = range_along(before, beams, rmax, normalize_angle(beams[j] + turn), o.cap);
      if (std::isnan(r)) continue;
      const double d = r - after[j];
      sum += std::min(d * d, cap2) / var2;
      ++overlap;
    }
    if (overlap < o.min_overlap) continue;
    const double cost = hits * sum / overlap + (turn - odometry_turn) * (turn - odometry_turn) / (2 * prior_var);
    if (cost < best_cost) {
      best_cost = cost;
      best = turn;
    }
  }
  return normalize_angle(best);
}

}  // namespace fleetmap::localization
