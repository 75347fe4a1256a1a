#pragma once
// The best pose near a place by a score (a log-likelihood of scans seen from it):
// coordinate ascent in x, y and theta with steps halved from (step_xy, step_theta) down
// to (min_step_xy, min_step_theta), each step tried both ways and kept while it helps.
// A global search's candidate lies on its 0.1 m grid and 1 degree heading steps; the
// product of a thousand beams tells its own place from a look-alike only once each is
// at its own best pose (docs/localization.md, "Settling on every scan").
#include <functional>

#include "client/localization/pose.h"

namespace fleetmap::localization {

struct RefineOptions {
  double step_xy = 0.1;             // metres: the search's cell
  double step_theta = deg2rad(1.0);  // radians: its heading step
  double min_step_xy = 0.0125;
  double min_step_theta = deg2rad(0.125);
  int max_moves = 40;               // accepted moves at most (bounds the work)
};

struct RefinedPlace {
  Pose pose;
  double score = 0;
  int evaluations = 0;
};

RefinedPlace refine_place(const Pose& start, const std::function<double(const Pose&)>& score,
                          const RefineOptions& options = {});

}  // namespace fleetmap::localization
