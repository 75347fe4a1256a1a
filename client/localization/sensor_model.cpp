#include "client/localization/sensor_model.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "client/localization/pose.h"

namespace fleetmap::localization {

namespace {
constexpr double kNegInf = -std::numeric_limits<double>::infinity();
// exp(-q) stays a normal double, and its inverse finite, up to here.
constexpr double kMaxExponent = 700;
}  // namespace

SensorModel::SensorModel(SensorModelOptions options) : options_(options) {
  if (!(options.sigma_m > 0)) throw std::invalid_argument("SensorModelOptions.sigma_m: expected > 0 metres");
  if (!(options.rmax > 0)) throw std::invalid_argument("SensorModelOptions.rmax: expected > 0 metres");
  if (!(options.alpha >= 0) || !(options.beta >= 0) || !(options.gamma >= 0) ||
      options.alpha + options.beta + options.gamma == 0)
    throw std::invalid_argument("SensorModelOptions.alpha, beta, gamma: expected >= 0 and not all 0");
  if (!(options.short_beyond >= 0)) throw std::invalid_argument("SensorModelOptions.short_beyond: expected >= 0 metres");
  normal_peak_ = options.alpha / (std::sqrt(2 * kPi) * options.sigma_m);
  log_normal_peak_ = options.alpha > 0 ? std::log(normal_peak_) : kNegInf;
  inv_two_var_ = 1 / (2 * options.sigma_m * options.sigma_m);
  uniform_ = options.beta / options.rmax;
  floor_ = options.gamma / (2 * options.rmax);
  short_floor_ = options.short_beyond > 0 ? -options.short_beyond : kNegInf;
}

double SensorModel::uniform_terms(double delta) const {
  // seed 000 eq. (5): the uniform term covers [-RMAX, 0], measured shorter than expected.
  const double u = (delta <= 0 && delta >= -options_.rmax) ? uniform_ : 0.0;
  return u + (std::fabs(delta) <= options_.rmax ? floor_ : 0.0);
}

double SensorModel::likelihood(double delta) const {
  delta = clamp_short(delta);
  return normal_peak_ * std::exp(-delta * delta * inv_two_var_) + uniform_terms(delta);
}

double SensorModel::log_likelihood(double delta) const { return log_likelihood_of_delta(clamp_short(delta)); }

double SensorModel::log_likelihood_of_delta(double delta) const {
  const double q = delta * delta * inv_two_var_;
  const double u = uniform_terms(delta);
  const double log_normal = log_normal_peak_ - q;
  if (!(u > 0)) return log_normal;
  // log(e^a + e^b) without overflow or underflow.
  const double log_u = std::log(u);
  const double hi = std::max(log_normal, log_u), lo = std::min(log_normal, log_u);
  return hi + std::log1p(std::exp(lo - hi));
}

double SensorModel::log_weight(const double* measured, const double* synthetic, size_t n,
                               const uint8_t* foreground) const {
  if (options_.combination == BeamCombination::Product) {
    double s = 0;
    for (size_t j = 0; j < n; ++j) s += log_likelihood_of_delta(beam_delta(measured[j], synthetic[j], foreground, j));
    return s;
  }
  // seed 000 eq. (6): 1 / sum_j 1/L_j. In doubles while every 1/L_j is finite (the usual
  // case: with sigma_m 0.5 m and RMAX 15 m the exponent is at most 450), else in logs.
  double inv_sum = 0;
  for (size_t j = 0; j < n; ++j) {
    const double d = beam_delta(measured[j], synthetic[j], foreground, j);
    const double q = d * d * inv_two_var_;
    if (q > kMaxExponent) return log_weight_harmonic_slow(measured, synthetic, n, foreground);
    inv_sum += 1 / (normal_peak_ * std::exp(-q) + uniform_terms(d));
  }
  if (n == 0) return 0;
  return -std::log(inv_sum);
}

double SensorModel::log_weight_harmonic_slow(const double* measured, const double* synthetic, size_t n,
                                             const uint8_t* foreground) const {
  // -log sum_j exp(-log L_j), by the log-sum-exp trick.
  double top = kNegInf;
  for (size_t j = 0; j < n; ++j)
    top = std::max(top, -log_likelihood_of_delta(beam_delta(measured[j], synthetic[j], foreground, j)));
  if (std::isinf(top)) return top > 0 ? kNegInf : 0.0;
  double s = 0;
  for (size_t j = 0; j < n; ++j)
    s += std::exp(-log_likelihood_of_delta(beam_delta(measured[j], synthetic[j], foreground, j)) - top);
  return -(top + std::log(s));
}

}  // namespace fleetmap::localization
