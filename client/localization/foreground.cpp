#include "client/localization/foreground.h"

#include <algorithm>
#include <cmath>

namespace fleetmap::localization {

namespace {

struct Segment {
  size_t first, last;  // beams, inclusive
};

}  // namespace

std::vector<uint8_t> foreground_returns(const std::vector<double>& ranges, const std::vector<double>& beam_angles,
                                        double rmax, const ForegroundOptions& options) {
  const size_t n = std::min(ranges.size(), beam_angles.size());
  std::vector<uint8_t> out(ranges.size(), 0);
  auto hit = [&](size_t j) { return ranges[j] < rmax; };
  // Break where a return is missing or the range jumps.
  std::vector<Segment> segments;
  for (size_t j = 0; j < n; ++j) {
    if (!hit(j)) continue;
    if (!segments.empty() && segments.back().last + 1 == j && std::fabs(ranges[j] - ranges[j - 1]) <= options.jump)
      segments.back().last = j;
    else
      segments.push_back({j, j});
  }
  auto width = [&](const Segment& s) {
    const double a0 = beam_angles[s.first], a1 = beam_angles[s.last];
    const double dx = ranges[s.last] * std::cos(a1) - ranges[s.first] * std::cos(a0);
    const double dy = ranges[s.last] * std::sin(a1) - ranges[s.first] * std::sin(a0);
    return std::hypot(dx, dy);
  };
  // The beam just outside a segment on one side: its range, or NaN when unknown (past
  // the field of view, or dropped already). No return reaches farther than any wall.
  auto beside = [&](size_t j, bool inside_fov) -> double {
    if (!inside_fov || out[j]) return NAN;
    return hit(j) ? ranges[j] : rmax;
  };
  std::vector<uint8_t> done(segments.size(), 0);
  for (int round = 0; round < options.max_rounds; ++round) {
    std::vector<size_t> dropped;
    for (size_t i = 0; i < segments.size(); ++i) {
      if (done[i]) continue;
      const Segment& s = segments[i];
      if (width(s) > options.max_width) continue;
      double nearest = INFINITY;
      for (size_t k = s.first; k <= s.last; ++k) nearest = std::min(nearest, ranges[k]);
      const double left = beside(s.first - 1, s.first > 0);
      const double right = beside(s.last + 1, s.last + 1 < n);
      if (std::isnan(left) && std::isnan(right)) continue;
      const bool in_front = (std::isnan(left) || left > nearest + options.jump) &&
                            (std::isnan(right) || right > nearest + options.jump);
      if (in_front) dropped.push_back(i);
    }
    if (dropped.empty()) break;
    // Marked after the round, so one round's verdicts do not depend on scan order.
    for (size_t i : dropped) {
      done[i] = 1;
      for (size_t k = segments[i].first; k <= segments[i].last; ++k) out[k] = 1;
    }
  }
  return out;
}

}  // namespace fleetmap::localization
