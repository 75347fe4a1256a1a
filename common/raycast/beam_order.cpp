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
  order.unit.resize(n);
  for (size_t k = 0; k < n; ++k) {
    order.pseudo[k] = p[order.beam[k]];
    order.unit[k] = ray_direction(rel[order.beam[k]]);
  }
  order.first.resize(BeamOrder::kBins + 1);
  for (int b = 0; b <= BeamOrder::kBins; ++b)
    order.first[b] = static_cast<uint32_t>(
        std::lower_bound(order.pseudo.begin(), order.pseudo.end(), static_cast<double>(b) / BeamOrder::kBinsPerUnit) -
        order.pseudo.begin());
  return order;
}

}  // namespace fleetmap
