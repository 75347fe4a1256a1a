#include "client/localization/stitched_scan.h"

#include <cmath>

namespace fleetmap::localization {

StitchedScan stitch_scans(const std::vector<const std::vector<double>*>& scans, const std::vector<Odometry>& odometry,
                          const std::vector<double>& beams, double rmax, size_t max_points) {
  StitchedScan s;
  const size_t n = scans.size();
  if (n == 0) return s;
  // Chained in the first scan's frame, then made relative to the latest.
  s.poses.resize(n);
  for (size_t k = 1; k < n; ++k) s.poses[k] = compose(s.poses[k - 1], odometry[k]);
  const Pose last = s.poses.back();
  for (Pose& p : s.poses) {
    const Odometry r = between(last, p);
    p = {r.dx, r.dy, r.dtheta};
  }
  for (size_t k = n; k-- > 0;) {
    const Pose& p = s.poses[k];
    const std::vector<double>& scan = *scans[k];
    for (size_t j = 0; j < beams.size() && j < scan.size(); ++j) {
      const double r = scan[j];
      if (!(r < rmax)) continue;
      const double a = p.theta + beams[j];
      const double x = p.x + r * std::cos(a), y = p.y + r * std::sin(a);
      s.ranges.push_back(std::hypot(x, y));
      s.angles.push_back(std::atan2(y, x));
    }
  }
  if (max_points > 0 && s.ranges.size() > max_points) {
    std::vector<double> r, a;
    for (size_t m = 0; m < max_points; ++m) {
      const size_t i = m * s.ranges.size() / max_points;
      r.push_back(s.ranges[i]);
      a.push_back(s.angles[i]);
    }
    s.ranges.swap(r);
    s.angles.swap(a);
  }
  return s;
}

}  // namespace fleetmap::localization
