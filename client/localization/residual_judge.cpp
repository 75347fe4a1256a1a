#include "client/localization/residual_judge.h"

#include <algorithm>
#include <limits>
#include <optional>
#include <utility>

#include "client/localization/parallel.h"

namespace fleetmap::localization {

namespace {

double fit(const RegisteredScans& s) { return s.score(s.place); }

}  // namespace

ResidualJudge::ResidualJudge(const AmbiguityOptions& o, PlaceScore residual, RegisteredResidual registered)
    : o_(o), residual_(std::move(residual)), registered_(std::move(registered)) {
  // Refinement by residual: its peak is narrow, so the steps go finer than the filter's
  // settling.
  fine_.min_step_xy = 0.003;
  fine_.min_step_theta = deg2rad(0.03);
  fine_.max_moves = 80;
  coarse_.step_xy = o.place_step_xy;
  coarse_.step_theta = o.place_step_theta;
  coarse_.min_step_xy = o.place_step_xy / 2;
  coarse_.min_step_theta = o.place_step_theta / 2;
  coarse_.max_moves = o.place_moves;
}

ResidualJudge::Reference ResidualJudge::reference_at(const Pose& place) const {
  Reference r{refine_place(place, residual_, fine_), residual_};
  if (registered_) r = register_at(r.place.pose, false);
  return r;
}

ResidualJudge::Reference ResidualJudge::register_at(const Pose& p, bool move) const {
  if (!move) {
    // The others are refined on these scans from where they are (a twin start of the
    // campus, seed 7373, was lost when they started from the latest scan's registered
    // pose instead).
    const RegisteredScans scans = registered_(p);
    const Odometry to_latest = between(p, scans.place);
    return Reference{{p, fit(scans), 0},
                     [score = scans.score, to_latest](const Pose& q) { return score(compose(q, to_latest)); }};
  }
  const Pose at = refine_place(p, [&](const Pose& q) { return fit(registered_(q)); }, coarse_).pose;
  const RegisteredScans scans = registered_(at);
  return Reference{{scans.place, fit(scans), 0}, scans.score};
}

std::vector<ResidualJudge::Kept> ResidualJudge::judge(const std::vector<Pose>& others, std::vector<Pose> held,
                                                      const Reference& reference, bool moved,
                                                      const std::vector<Kept>& plain_kept) const {
  std::vector<bool> was_kept(others.size(), false);
  for (const Kept& k : plain_kept) was_kept[k.other] = true;
  const RefinedPlace& ref = reference.place;
  held.push_back(ref.pose);
  const auto apart = [&](const Pose& q) { return !near_any(held, q, o_.min_separation); };
  // Each refined (and, near enough, registered at itself) on o.threads threads: this is
  // most of the verdict's time. Then taken in order, as places apart.
  const size_t n = others.size();
  std::vector<std::optional<RefinedPlace>> refined(n);  // none: not apart from the places held
  std::vector<double> self(n, -std::numeric_limits<double>::infinity());
  parallel_for(std::max(1, o_.threads), n, [&](int, size_t begin, size_t end) {
    for (size_t k = begin; k < end; ++k) {
      if (!apart(others[k])) continue;
      const RefinedPlace& r = refined[k].emplace(refine_place(others[k], reference.judge, fine_));
      if (!registered_ || r.score >= ref.score - o_.rival_margin_z2) continue;
      if (moved && was_kept[k]) {
        // A place kept against the unmoved reference is moved too before it is dropped.
        self[k] = register_at(r.pose, true).place.score;
        continue;
      }
      if (r.score < ref.score - o_.rival_register_window_z2) continue;
      self[k] = register_at(r.pose, false).place.score;
      // Against a moved reference, moved too where that can decide (moving raised the
      // reference's fit by up to 0.07 per beam on the campus, less than the margin).
      if (moved && self[k] < ref.score && self[k] >= ref.score - o_.rival_margin_z2)
        self[k] = std::max(self[k], register_at(r.pose, true).place.score);
    }
  });
  std::vector<Kept> kept;
  for (size_t k = 0; k < n; ++k) {
    if (!refined[k] || !apart(others[k]) || !apart(refined[k]->pose)) continue;
    const RefinedPlace& r = *refined[k];
    if (!(r.score >= ref.score - o_.rival_margin_z2) && !(self[k] >= ref.score)) continue;
    held.push_back(r.pose);
    kept.push_back({k, r.pose});
  }
  return kept;
}

bool ResidualJudge::ruled_out(const Pose& other, const Reference& reference, double margin) const {
  const double line = reference.place.score - margin;
  const RefinedPlace r = refine_place(other, reference.judge, fine_);
  if (r.score >= line) return false;
  return !registered_ || register_at(r.pose, false).place.score < line;
}

}  // namespace fleetmap::localization
