#include "client/localization/motion_model.h"

#include <cmath>

namespace fleetmap::localization {

OdometryDecomposition MotionModel::decompose(const Odometry& u) const {
  OdometryDecomposition d;
  d.trans = std::hypot(u.dx, u.dy);
  // Below a micrometre the direction of the displacement is noise: a pure rotation.
  d.rot1 = d.trans < 1e-6 ? 0.0 : std::atan2(u.dy, u.dx);
  if (std::fabs(d.rot1) > kPi / 2) {  // backwards
    d.rot1 = normalize_angle(d.rot1 + kPi);
    d.trans = -d.trans;
  }
  d.rot2 = angle_diff(u.dtheta, d.rot1);
  const MotionNoise& a = noise_;
  const double r1 = d.rot1 * d.rot1, t = d.trans * d.trans, r2 = d.rot2 * d.rot2;
  d.sd_rot1 = std::sqrt(a.alpha1 * r1 + a.alpha2 * t);
  d.sd_trans = std::sqrt(a.alpha3 * t + a.alpha4 * (r1 + r2));
  d.sd_rot2 = std::sqrt(a.alpha1 * r2 + a.alpha2 * t);
  return d;
}

Odometry MotionModel::sample(const Odometry& u, std::mt19937_64& rng) const {
  const OdometryDecomposition d = decompose(u);
  std::normal_distribution<double> n01(0.0, 1.0);
  const double rot1 = d.rot1 + d.sd_rot1 * n01(rng);
  const double trans = d.trans + d.sd_trans * n01(rng);
  const double rot2 = d.rot2 + d.sd_rot2 * n01(rng);
  return {trans * std::cos(rot1), trans * std::sin(rot1), normalize_angle(rot1 + rot2)};
}

}  // namespace fleetmap::localization
