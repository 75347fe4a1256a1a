#include "client/localization/resampling.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <stdexcept>
#include <unordered_set>

namespace fleetmap::localization {

std::vector<size_t> low_variance_resample(const std::vector<double>& weights, size_t n, std::mt19937_64& rng) {
  const double total = std::accumulate(weights.begin(), weights.end(), 0.0);
  if (weights.empty() || !(total > 0)) throw std::invalid_argument("low_variance_resample: weights: expected a positive sum");
  std::vector<size_t> out;
  out.reserve(n);
  if (n == 0) return out;
  const double step = total / n;
  std::uniform_real_distribution<double> u(0.0, step);
  const double r = u(rng);
  size_t i = 0;
  double c = weights[0];
  for (size_t m = 0; m < n; ++m) {
    const double target = r + m * step;
    while (target > c && i + 1 < weights.size()) c += weights[++i];
    out.push_back(i);
  }
  return out;
}

double normal_upper_quantile(double p) {
  if (!(p > 0 && p < 1)) throw std::invalid_argument("normal_upper_quantile: p: expected 0 < p < 1");
  // Bisection on P(N > z) = erfc(z / sqrt 2) / 2, decreasing in z; computed once per filter.
  double lo = -40, hi = 40;
  for (int k = 0; k < 200; ++k) {
    const double mid = (lo + hi) / 2;
    (0.5 * std::erfc(mid / std::sqrt(2.0)) > p ? lo : hi) = mid;
  }
  return (lo + hi) / 2;
}

double kld_required_count(size_t k, double epsilon, double z) {
  if (k < 2) return 1;
  const double km1 = static_cast<double>(k - 1);
  const double a = 2 / (9 * km1);
  const double b = 1 - a + std::sqrt(a) * z;
  return km1 / (2 * epsilon) * b * b * b;
}

std::vector<size_t> kld_resample(const std::vector<Pose>& poses, const std::vector<double>& weights,
                                 const KldOptions& o, std::mt19937_64& rng) {
  if (poses.size() != weights.size() || poses.empty())
    throw std::invalid_argument("kld_resample: poses and weights: expected the same, non-zero size");
  std::vector<double> cumulative(weights.size());
  std::partial_sum(weights.begin(), weights.end(), cumulative.begin());
  const double total = cumulative.back();
  if (!(total > 0)) throw std::invalid_argument("kld_resample: weights: expected a positive sum");
  const double z = normal_upper_quantile(o.delta);
  const size_t lo = std::max<size_t>(1, std::min(o.min_particles, o.max_particles));
  std::uniform_real_distribution<double> u(0.0, total);
  std::unordered_set<uint64_t> bins;
  std::vector<size_t> out;
  out.reserve(o.max_particles);
  while (out.size() < o.max_particles) {
    const size_t i = std::min<size_t>(std::upper_bound(cumulative.begin(), cumulative.end(), u(rng)) - cumulative.begin(),
                                      weights.size() - 1);
    out.push_back(i);
    // 21 bits per coordinate: +-1 000 000 bins, far more than any map needs.
    const Pose& p = poses[i];
    const auto key = [](double v, double cell) {
      return static_cast<uint64_t>(static_cast<int64_t>(std::floor(v / cell)) & 0x1FFFFF);
    };
    bins.insert(key(p.x, o.bin_xy) << 42 | key(p.y, o.bin_xy) << 21 | key(p.theta, o.bin_theta));
    if (out.size() >= lo && static_cast<double>(out.size()) >= kld_required_count(bins.size(), o.epsilon, z)) break;
  }
  return out;
}

}  // namespace fleetmap::localization
