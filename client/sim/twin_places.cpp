#include "client/sim/twin_places.h"

#include <algorithm>
#include <cmath>

#include "client/localization/place_refinement.h"

namespace fleetmap::localization {

TwinCheck find_twin(const RayCaster& world, const GlobalSearch& search, const std::vector<Pose>& path,
                    const std::vector<double>& beam_angles, double half_width, const TwinOptions& options) {
  TwinCheck out;
  const size_t n = beam_angles.size();
  if (path.empty() || n == 0) return out;
  const Pose& start = path.front();
  out.place = start;
  const double rmax = world.options().rmax;
  // Each scan's pose in the start's frame, and the truth's noiseless ranges.
  std::vector<Odometry> relative;
  std::vector<double> truth(path.size() * n);
  for (size_t u = 0; u < path.size(); ++u) {
    relative.push_back(between(start, path[u]));
    world.cast_scan(path[u].point(), path[u].theta, beam_angles, truth.data() + u * n);
  }
  // The returns as points seen from the start (stitched_scan.h does this from odometry).
  std::vector<double> ranges, angles;
  for (size_t u = 0; u < path.size(); ++u) {
    const Odometry& q = relative[u];
    for (size_t j = 0; j < n; ++j) {
      const double r = truth[u * n + j];
      if (r >= rmax) continue;
      const double a = q.dtheta + beam_angles[j];
      const double x = q.dx + r * std::cos(a), y = q.dy + r * std::sin(a);
      ranges.push_back(std::hypot(x, y));
      angles.push_back(std::atan2(y, x));
    }
  }
  if (ranges.empty()) return out;
  const std::vector<Candidate> candidates = search.search(ranges, angles, INFINITY, start.theta, half_width,
                                                          options.candidates);
  std::vector<double> cast(n);
  auto mean_z2 = [&](const Pose& p) {
    double sum = 0;
    for (size_t u = 0; u < path.size(); ++u) {
      const Pose q = compose(p, relative[u]);
      world.cast_scan(q.point(), q.theta, beam_angles, cast.data());
      for (size_t j = 0; j < n; ++j) {
        const double z = (cast[j] - truth[u * n + j]) / options.sigma;
        sum += std::min(z * z, options.max_z2);
      }
    }
    return sum / static_cast<double>(path.size() * n);
  };
  // Finer than the filter's settling: an exact twin off the search's grid by a few
  // millimetres must come out as one.
  RefineOptions refine;
  refine.min_step_xy = 0.003;
  refine.min_step_theta = deg2rad(0.03);
  refine.max_moves = 80;
  for (const Candidate& c : candidates) {
    if (distance(c.pose, start) < options.min_distance) continue;
    ++out.tried;
    const RefinedPlace r = refine_place(c.pose, [&](const Pose& p) { return -mean_z2(p); }, refine);
    // Refined back onto the start, or turned out of the compass's interval: not another place.
    if (distance(r.pose, start) < options.min_distance) continue;
    if (std::fabs(angle_diff(r.pose.theta, start.theta)) > half_width) continue;
    if (-r.score < out.mean_z2) {
      out.mean_z2 = -r.score;
      out.place = r.pose;
    }
    if (out.mean_z2 <= options.twin_mean_z2) {
      out.twin = true;
      break;
    }
  }
  return out;
}

}  // namespace fleetmap::localization
