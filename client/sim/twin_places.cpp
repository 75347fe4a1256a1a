#include "client/sim/twin_places.h"

#include <algorithm>
#include <cmath>

#include "client/localization/place_refinement.h"
#include "client/localization/stitched_scan.h"

namespace fleetmap::localization {

TwinCheck find_twin(const RayCaster& world, const GlobalSearch& search, const std::vector<Pose>& path,
                    const std::vector<double>& beam_angles, double half_width, const TwinOptions& options,
                    const std::vector<Pose>& also, const PeopleInPath* people) {
  TwinCheck out;
  const size_t n = beam_angles.size();
  if (path.empty() || n == 0) return out;
  const Pose& start = path.front();
  out.place = start;
  // The truth's noiseless scans, stitched newest first so that the frame is the start's
  // (stitched_scan.h): its poses are each scan's pose from the start.
  std::vector<std::vector<double>> truth(path.size(), std::vector<double>(n));
  std::vector<const std::vector<double>*> newest_first;
  std::vector<Odometry> steps;
  for (size_t u = path.size(); u-- > 0;) {
    world.cast_scan(path[u].point(), path[u].theta, beam_angles, truth[u].data());
    newest_first.push_back(&truth[u]);
    steps.push_back(u + 1 < path.size() ? between(path[u + 1], path[u]) : Odometry{});
  }
  const StitchedScan stitched = stitch_scans(newest_first, steps, beam_angles, world.options().rmax);
  if (stitched.ranges.empty()) return out;
  std::vector<Odometry> relative;  // relative[u]: path[u] from the start
  for (size_t u = 0; u < path.size(); ++u) {
    const Pose& q = stitched.poses[path.size() - 1 - u];
    relative.push_back({q.x, q.y, q.theta});
  }
  std::vector<Pose> candidates;
  if (options.candidates > 0)
    for (const Candidate& c : search.search(stitched.ranges, stitched.angles, INFINITY, start.theta, half_width,
                                            options.candidates))
      candidates.push_back(c.pose);
  candidates.insert(candidates.end(), also.begin(), also.end());
  // A record of the people of another shape than the path's scans is left out: the map
  // alone decides, rather than a read past its end.
  const auto scans_of_path = [&](const auto& per_scan) {
    return per_scan.size() == path.size() &&
           std::all_of(per_scan.begin(), per_scan.end(), [&](const auto& scan) { return scan.size() == n; });
  };
  if (people && !(scans_of_path(people->stopped) && scans_of_path(people->ranges))) people = nullptr;
  std::vector<double> cast(n);
  auto mean_z2 = [&](const Pose& p) {
    double sum = 0;
    for (size_t u = 0; u < path.size(); ++u) {
      const Pose q = compose(p, relative[u]);
      world.cast_scan(q.point(), q.theta, beam_angles, cast.data());
      for (size_t j = 0; j < n; ++j) {
        double z = (cast[j] - truth[u][j]) / options.sigma;
        if (people && people->stopped[u][j]) {
          // Only a wall in front of the person tells this place from the truth.
          const double reading = people->ranges[u][j];
          z = cast[j] < reading ? (cast[j] - reading) / options.sigma : 0;
        }
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
  for (const Pose& c : candidates) {
    if (distance(c, start) < options.min_distance) continue;
    ++out.tried;
    const RefinedPlace r = refine_place(c, [&](const Pose& p) { return -mean_z2(p); }, refine);
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
