#include "common/raycast/beam_order.h"

#include <cstring>
#include <numeric>

#include "common/raycast/ray_caster.h"

namespace fleetmap {

const BeamOrder& beam_order(const std::vector<double>& rel) {
  thread_local BeamOrder order;
  const size_t n = rel.size();
  if (order.angles.size() == n && !order.first.empty() &&
      (n == 0 || std::memcmp(order.angles.data(), rel.data(), n * sizeof(double)) == 0))
    return order;
  order.angles = rel;
  std::vector<double> p(n);
  for (size_t j = 0; j < n; ++j) p[j] = pseudo_angle(ray_direction(rel[j]));
  order.beam.resize(n);
  std::iota(order.beam.begin(), order.beam.end(), 0u);
  std::stable_sort(order.beam.begin(), order.beam.end(), [&](uint32_t l, uint32_t r) { return p[l] < p[r]; });
  order.pseudo.resize(n);
  order.unit_x.assign((n + 3) / 4 * 4, 0.0);
  order.unit_y.assign((n + 3) / 4 * 4, 0.0);
  for (size_t k = 0; k < n; ++k) {
    order.pseudo[k] = p[order.beam[k]];
    const Point u = ray_direction(rel[order.beam[k]]);
    order.unit_x[k] = u.x;
    order.unit_y[k] = u.y;
  }
  // The largest gap between cyclically consecutive beams; the arc is the rest.
  order.all_around = true;
  if (n > 0) {
    double gap = order.pseudo[0] + 4 - order.pseudo[n - 1];
    size_t after = 0;
    for (size_t k = 1; k < n; ++k)
      if (order.pseudo[k] - order.pseudo[k - 1] > gap) {
        gap = order.pseudo[k] - order.pseudo[k - 1];
        after = k;
      }
    order.arc_first = after;
    order.arc_last = (after + n - 1) % n;
    order.all_around = gap < 0.01;  // too small to skip anything, and safe from wrapping
  }
  order.first.resize(BeamOrder::kBins + 1);
  for (int b = 0; b <= BeamOrder::kBins; ++b)
    order.first[b] = static_cast<uint32_t>(
        std::lower_bound(order.pseudo.begin(), order.pseudo.end(), static_cast<double>(b) / BeamOrder::kBinsPerUnit) -
        order.pseudo.begin());
  order.rotated = n > 0;
  order.rotation = n > 0 ? order.beam[0] : 0;
  for (size_t k = 0; k < n; ++k) order.rotated &= order.beam[k] == (k + order.rotation) % n;
  order.one_per_bin = true;
  for (int b = 0; b < BeamOrder::kBins; ++b) order.one_per_bin &= order.first[b + 1] - order.first[b] <= 1;
  return order;
}

}  // namespace fleetmap
