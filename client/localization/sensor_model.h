#pragma once
// The laser sensor model of seed 000 section 4.1, eq. (4)-(6).
//
//   (4)  delta_j = ls_j^L - ls_j^i       measured range minus the particle's synthetic one
//   (5)  L(delta) = alpha N(0, sigma_m)(delta) + beta U(-RMAX, 0)(delta)
//   (6)  w^i(t) = w^i(t-1) / sum_j 1 / L(delta_j)
//
// N(0, sigma_m) is the normal density, 1 / (sqrt(2 pi) sigma_m) exp(-delta^2 / 2 sigma_m^2).
// The seed calls sigma_m a variance but gives it in metres (0.5 m); we read it as the
// standard deviation. U(-RMAX, 0) is the uniform density 1 / RMAX on [-RMAX, 0] and 0
// elsewhere: it applies only when the laser measured at most the synthetic range
// (delta <= 0), the ray stopped short of the modelled wall by something the map does not
// hold (people, cars, bikes). A ray that went further than the map allows (delta > 0)
// is explained by the normal term alone. Beams the laser returned at RMAX (nothing hit)
// are compared like any other: the synthetic ray of a good particle also ends at RMAX.
//
// Eq. (6) combines the beams by the inverse of the sum of their inverses (the harmonic
// mean divided by NL), close to the smallest L_j: one ray that meets a wall the laser
// did not see (delta of metres > 0) decides the particle's weight, and a particle that
// sees nothing at all (every delta <= 0, each L_j >= beta / RMAX) can outscore one a
// few centimetres from the truth whose rays graze a corner. BeamCombination::Product is
// the usual independent-beam product (Thrun et al. 2005, eq. 6.2), which
// ParticleFilterOptions::robust() uses; bench-localization measures both.
// Both are computed as logarithms so that no weight underflows.
//
// Beyond the seed, gamma adds a uniform floor on both sides, gamma U(-RMAX, RMAX) (Thrun
// et al.'s z_rand): eq. (5) floors only readings shorter than expected; the floor bounds
// what one grazing ray can cost.
//
// Beyond the seed, short_beyond (people in the scans, docs/localization.md "People in the
// scans"): a beam stopped more than short_beyond metres short of the synthetic range
// counts as stopped exactly short_beyond short, delta = max(delta, -short_beyond). Such
// a reading is explained by something the map does not hold, wherever the particle
// stands, so it gets one flat likelihood instead of a penalty that grows with the gap:
// otherwise a pose that puts walls where the people stand outscores the truth once
// people hide most beams. Readings longer than expected (through a wall) keep the full
// penalty, so a pose in open space does not win by "explaining" every wall as a person.
#include <cstddef>
#include <cstdint>

namespace fleetmap::localization {

enum class BeamCombination {
  Harmonic,  // seed 000 eq. (6), the default
  Product,   // prod_j L(delta_j)
};

struct SensorModelOptions {
  double alpha = 1.0;    // seed 000 eq. (5): weight of the normal term
  double beta = 0.1;     // seed 000 eq. (5): weight of the uniform term
  double sigma_m = 0.5;  // metres, standard deviation of the normal term
  double rmax = 15.0;    // metres, RMAX: the laser's range and the uniform's width
  // Not in the seed: gamma U(-RMAX, RMAX), a floor for readings off either way (Thrun
  // et al. 2005's z_rand); 0 keeps eq. (5) exactly.
  double gamma = 0.0;
  // Not in the seed: delta = max(delta, -short_beyond) (metres; 0 keeps eq. (5) exactly).
  double short_beyond = 0.0;
  // Not in the seed: short_beyond applies only to beams flagged foreground (foreground.h,
  // people); the others keep eq. (5) as written. On open ground a flat short term lets a
  // wrong place call far walls people (docs/localization.md, "Short only in front").
  bool short_only_foreground = false;
  BeamCombination combination = BeamCombination::Harmonic;
};

class SensorModel {
 public:
  // Throws std::invalid_argument when sigma_m or rmax is not positive, or alpha, beta or
  // gamma is negative, or all are zero, or short_beyond is negative.
  explicit SensorModel(SensorModelOptions options = {});

  // Eq. (5) for one beam, and its natural logarithm (exact also where L underflows).
  double likelihood(double delta) const;
  double log_likelihood(double delta) const;

  // The logarithm of the factor of eq. (6) (or of the product) that multiplies the
  // previous weight, for n beams: measured[j] against synthetic[j].
  // foreground (optional, per beam, foreground.h): which beams short_only_foreground lets
  // stop short.
  double log_weight(const double* measured, const double* synthetic, size_t n,
                    const uint8_t* foreground = nullptr) const;

  const SensorModelOptions& options() const { return options_; }

 private:
  double log_likelihood_of_delta(double delta) const;  // log_likelihood without the clamp
  double clamp_short(double delta) const { return delta < short_floor_ ? short_floor_ : delta; }
  double uniform_terms(double delta) const;  // beta U(-RMAX, 0) + gamma U(-RMAX, RMAX)
  double log_weight_harmonic_slow(const double* measured, const double* synthetic, size_t n,
                                  const uint8_t* foreground) const;
  // The beam's eq. (4) delta, clamped by short_beyond where it applies to the beam.
  double beam_delta(double measured, double synthetic, const uint8_t* foreground, size_t j) const {
    const double d = measured - synthetic;
    if (options_.short_only_foreground && !(foreground && foreground[j])) return d;
    return clamp_short(d);
  }

  SensorModelOptions options_;
  double normal_peak_;      // alpha / (sqrt(2 pi) sigma_m)
  double log_normal_peak_;
  double inv_two_var_;      // 1 / (2 sigma_m^2)
  double uniform_;          // beta / RMAX
  double floor_;            // gamma / (2 RMAX)
  double short_floor_;      // -short_beyond, or -inf when off
};

}  // namespace fleetmap::localization
