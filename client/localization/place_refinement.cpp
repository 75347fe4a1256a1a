#include "client/localization/place_refinement.h"

#include <algorithm>

namespace fleetmap::localization {

RefinedPlace refine_place(const Pose& start, const std::function<double(const Pose&)>& score,
                          const RefineOptions& o) {
  RefinedPlace best{start, score(start), 1};
  double sxy = o.step_xy, st = o.step_theta;
  int moves = 0;
  while (moves < o.max_moves) {
    bool moved = false;
    for (int axis = 0; axis < 3 && moves < o.max_moves; ++axis)
      for (int sign : {1, -1}) {
        Pose p = best.pose;
        const double step = sign * (axis < 2 ? sxy : st);
        if (axis == 0) p.x += step;
        if (axis == 1) p.y += step;
        if (axis == 2) p.theta = normalize_angle(p.theta + step);
        const double s = score(p);
        ++best.evaluations;
        if (s > best.score) {
          best.pose = p;
          best.score = s;
          moved = true;
          ++moves;
          break;  // the other way cannot help along this axis now
        }
      }
    if (moved) continue;
    if (sxy <= o.min_step_xy && st <= o.min_step_theta) break;
    sxy = std::max(o.min_step_xy, sxy / 2);
    st = std::max(o.min_step_theta, st / 2);
  }
  return best;
}

}  // namespace fleetmap::localization
