#include "client/localization/particle_filter.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "client/localization/parallel.h"
#include "common/grid_ray_caster.h"

namespace fleetmap::localization {

namespace {

SensorModelOptions sensor_options(const ParticleFilterOptions& o) {
  SensorModelOptions s = o.sensor;
  s.rmax = o.laser.rmax;  // one RMAX: the laser's range is the uniform term's width
  return s;
}

std::mt19937_64 seeded(uint64_t seed, uint64_t stream) {
  std::seed_seq seq{static_cast<uint32_t>(seed), static_cast<uint32_t>(seed >> 32), static_cast<uint32_t>(stream)};
  return std::mt19937_64(seq);
}

}  // namespace

ParticleFilter::ParticleFilter(const Map& map, ParticleFilterOptions options)
    : ParticleFilter(map, std::make_shared<GridRayCaster>(map, options.laser), options) {}

ParticleFilter::ParticleFilter(const Map& map, std::shared_ptr<const RayCaster> caster, ParticleFilterOptions options)
    : options_(options),
      beams_(evenly_spread_angles(options.beams, options.fov)),
      sensor_(sensor_options(options)),
      motion_(options.motion),
      compass_(options.compass_half_width),
      rng_(seeded(options.seed, 0xFFFFFFFFu)) {
  if (options.particles == 0) throw std::invalid_argument("ParticleFilterOptions.particles: expected > 0");
  if (options.beams <= 0) throw std::invalid_argument("ParticleFilterOptions.beams: expected > 0");
  options_.threads = std::max(1, options.threads);
  for (int k = 0; k < options_.threads; ++k) chunk_rngs_.push_back(seeded(options.seed, k));
  set_map(map, std::move(caster));
}

void ParticleFilter::set_map(const Map& map) { set_map(map, std::make_shared<GridRayCaster>(map, options_.laser)); }

void ParticleFilter::set_map(const Map& map, std::shared_ptr<const RayCaster> caster) {
  if (!caster) throw std::invalid_argument("ParticleFilter::set_map: caster: expected non-null");
  caster_ = std::move(caster);
  free_space_ = std::make_unique<FreeSpace>(map);
}

void ParticleFilter::init_global(std::optional<double> compass) {
  const size_t n = options_.particles;
  poses_.resize(n);
  std::uniform_real_distribution<double> any_heading(-kPi, kPi);
  for (Pose& p : poses_) {
    const Point q = free_space_->sample(rng_);
    p = {q.x, q.y, compass ? compass_.sample(*compass, rng_) : any_heading(rng_)};
  }
  weights_.assign(n, 1.0 / n);
}

void ParticleFilter::init_pose(const Pose& pose, double sd_xy, double sd_theta) {
  const size_t n = options_.particles;
  poses_.resize(n);
  std::normal_distribution<double> n01(0.0, 1.0);
  for (Pose& p : poses_)
    p = {pose.x + sd_xy * n01(rng_), pose.y + sd_xy * n01(rng_), normalize_angle(pose.theta + sd_theta * n01(rng_))};
  weights_.assign(n, 1.0 / n);
}

void ParticleFilter::predict(const Odometry& odometry) {
  parallel_for(options_.threads, poses_.size(), [&](int k, size_t begin, size_t end) {
    std::mt19937_64& rng = chunk_rngs_[k];
    for (size_t i = begin; i < end; ++i) poses_[i] = motion_.sample(poses_[i], odometry, rng);
  });
}

void ParticleFilter::update(const std::vector<double>& ranges, std::optional<double> compass) {
  if (ranges.size() != beams_.size())
    throw std::invalid_argument("ParticleFilter::update: ranges: expected " + std::to_string(beams_.size()) +
                                " beams, got " + std::to_string(ranges.size()));
  if (poses_.empty()) throw std::logic_error("ParticleFilter::update: no particles (call init_global or init_pose)");
  const bool use_compass = compass && options_.compass_weight;
  const RayCaster& caster = *caster_;
  parallel_for(options_.threads, poses_.size(), [&](int, size_t begin, size_t end) {
    std::vector<double> synthetic(beams_.size());
    for (size_t i = begin; i < end; ++i) {
      const Pose& p = poses_[i];
      caster.cast_scan(p.point(), p.theta, beams_, synthetic.data());
      // seed 000 eq. (6): w(t) = w(t-1) * 1 / sum_j 1 / L(delta_j); kept as logarithms.
      double lw = std::log(weights_[i]) + sensor_.log_weight(ranges.data(), synthetic.data(), beams_.size());
      if (use_compass) lw += compass_.log_likelihood(p.theta, *compass);
      weights_[i] = lw;  // a log-weight until normalize_weights()
    }
  });
  normalize_weights();
  ++updates_;
  double sum_sq = 0;
  for (double w : weights_) sum_sq += w * w;
  if (1 / sum_sq < options_.resample_threshold * poses_.size()) {
    resample();
    roughen();
  }
}

void ParticleFilter::normalize_weights() {
  // weights_ holds log-weights here.
  double top = -std::numeric_limits<double>::infinity();
  for (double lw : weights_)
    if (!std::isnan(lw)) top = std::max(top, lw);
  if (std::isinf(top)) {  // every particle impossible: start again from equal weights
    weights_.assign(weights_.size(), 1.0 / weights_.size());
    return;
  }
  double sum = 0;
  for (double& w : weights_) sum += (w = std::isnan(w) ? 0.0 : std::exp(w - top));
  for (double& w : weights_) w /= sum;
}

void ParticleFilter::resample() {
  const std::vector<size_t> idx = options_.adaptive ? kld_resample(poses_, weights_, options_.kld, rng_)
                                                    : low_variance_resample(weights_, options_.particles, rng_);
  std::vector<Pose> next(idx.size());
  for (size_t m = 0; m < idx.size(); ++m) next[m] = poses_[idx[m]];
  poses_ = std::move(next);
  weights_.assign(poses_.size(), 1.0 / poses_.size());
  ++resamplings_;
}

void ParticleFilter::roughen() {
  if (!(options_.roughening > 0) || poses_.size() < 2) return;
  const PoseEstimate e = estimate();
  // Per-dimension standard deviations of the (equally weighted) resampled cloud.
  double vx = 0, vy = 0;
  for (const Pose& p : poses_) {
    vx += (p.x - e.pose.x) * (p.x - e.pose.x);
    vy += (p.y - e.pose.y) * (p.y - e.pose.y);
  }
  const double n = static_cast<double>(poses_.size());
  const double scale = options_.roughening * std::pow(n, -1.0 / 3.0);
  const double sx = scale * std::sqrt(vx / n), sy = scale * std::sqrt(vy / n), st = scale * e.spread_theta;
  parallel_for(options_.threads, poses_.size(), [&](int k, size_t begin, size_t end) {
    std::mt19937_64& rng = chunk_rngs_[k];
    std::normal_distribution<double> n01(0.0, 1.0);
    for (size_t i = begin; i < end; ++i) {
      Pose& p = poses_[i];
      p = {p.x + sx * n01(rng), p.y + sy * n01(rng), normalize_angle(p.theta + st * n01(rng))};
    }
  });
}

PoseEstimate ParticleFilter::estimate() const {
  PoseEstimate e;
  e.particles = poses_.size();
  if (poses_.empty()) return e;
  double sw = 0, mx = 0, my = 0, sc = 0, ss = 0, sum_sq = 0;
  for (size_t i = 0; i < poses_.size(); ++i) {
    const double w = weights_[i];
    const Pose& p = poses_[i];
    sw += w;
    mx += w * p.x;
    my += w * p.y;
    sc += w * std::cos(p.theta);
    ss += w * std::sin(p.theta);
    sum_sq += w * w;
  }
  mx /= sw;
  my /= sw;
  double var = 0;
  for (size_t i = 0; i < poses_.size(); ++i) {
    const Pose& p = poses_[i];
    var += weights_[i] * ((p.x - mx) * (p.x - mx) + (p.y - my) * (p.y - my));
  }
  const double r = std::min(1.0, std::hypot(sc, ss) / sw);
  e.pose = {mx, my, std::atan2(ss, sc)};
  e.spread_xy = std::sqrt(var / sw);
  e.spread_theta = r > 0 ? std::sqrt(-2 * std::log(r)) : kPi;
  e.n_eff = sw * sw / sum_sq;
  e.converged = e.spread_xy < options_.converged_xy && e.spread_theta < options_.converged_theta;
  return e;
}

}  // namespace fleetmap::localization
