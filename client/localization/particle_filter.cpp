#include "client/localization/particle_filter.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>

#include "client/localization/parallel.h"
#include "client/localization/place_refinement.h"
#include "client/localization/residual_judge.h"
#include "client/localization/stitched_scan.h"
#include "client/localization/turn_registration.h"
#include "common/raycast/sweep_ray_caster.h"

namespace fleetmap::localization {

namespace {

SensorModelOptions sensor_options(const ParticleFilterOptions& o) {
  SensorModelOptions s = o.sensor;
  s.rmax = o.laser.rmax;  // one RMAX: the laser's range is the uniform term's width
  return s;
}

SensorModelOptions global_sensor_options(const ParticleFilterOptions& o) {
  SensorModelOptions s = sensor_options(o);
  if (o.global_short_beyond >= 0) s.short_beyond = o.global_short_beyond;
  return s;
}
SensorModelOptions search_sensor_options(const ParticleFilterOptions& o) {
  SensorModelOptions s = global_sensor_options(o);
  if (o.search_short_only_foreground) s.short_only_foreground = true;
  return s;
}

std::mt19937_64 seeded(uint64_t seed, uint64_t stream) {
  std::seed_seq seq{static_cast<uint32_t>(seed), static_cast<uint32_t>(seed >> 32), static_cast<uint32_t>(stream)};
  return std::mt19937_64(seq);
}

// Weighted mean of poses[i] for the i where take(i): (x, y) and circular theta; the sum
// of weights, and of their cosines and sines, for the spreads.
struct WeightedMean {
  Pose pose;
  double weight = 0, cos_sum = 0, sin_sum = 0;
};

template <typename Take>
WeightedMean weighted_mean(const std::vector<Pose>& poses, const std::vector<double>& weights, Take take) {
  WeightedMean m;
  double mx = 0, my = 0;
  for (size_t i = 0; i < poses.size(); ++i) {
    if (!take(i)) continue;
    const double w = weights[i];
    m.weight += w;
    mx += w * poses[i].x;
    my += w * poses[i].y;
    m.cos_sum += w * std::cos(poses[i].theta);
    m.sin_sum += w * std::sin(poses[i].theta);
  }
  if (m.weight > 0) m.pose = {mx / m.weight, my / m.weight, std::atan2(m.sin_sum, m.cos_sum)};
  return m;
}

// Sum over the particles of w(i) d d^T, d = position - mean: the covariance of x and y
// times the weights' sum.
template <typename Weight>
Eigen::Matrix2d position_scatter(const std::vector<Pose>& poses, const Pose& mean, Weight w) {
  Eigen::Matrix2d s = Eigen::Matrix2d::Zero();
  const Eigen::Vector2d m = position(mean);
  for (size_t i = 0; i < poses.size(); ++i) {
    const Eigen::Vector2d d = position(poses[i]) - m;
    s.noalias() += (w(i) * d) * d.transpose();
  }
  return s;
}

uint64_t cell_key(int64_t ix, int64_t iy) { return static_cast<uint64_t>(ix) << 32 ^ static_cast<uint32_t>(iy); }

}  // namespace

SensorModelOptions ParticleFilterOptions::tracking_sensor() const {
  SensorModelOptions s = sensor_options(*this);
  s.sigma_m = tracking_sigma();
  return s;
}

ParticleFilterOptions ParticleFilterOptions::robust() {
  ParticleFilterOptions o;
  o.sensor.combination = BeamCombination::Product;
  o.sensor.gamma = 0.1;
  o.tempering_ess = 0.3;
  o.tempering_stages = 3;
  o.global_density = 0.3;
  return o;
}

ParticleFilterOptions ParticleFilterOptions::robust_search() {
  ParticleFilterOptions o = robust();
  o.global_search = true;
  o.global_density = 0;  // the search replaces the uniform cloud
  // Tracking among people (sensor_model.h's short_beyond): a beam stopped more than 0.3 m
  // short counts as 0.3 m short. Without it, 30 people hid the walls and pulled the cloud
  // onto them: 1.3 m RMS over 300 m of GDC1. 0.3 m, not 0.5: a person at a wall stops
  // beams 0.45-0.65 m short, and at 0.5 those beams still pulled the cloud towards the
  // wall (docs/localization.md, "The flat short term from 0.3 m"). The global phase keeps
  // eq. (5) as written: on open ground a wrong place calls every far wall it lacks a
  // person, and the campus's global tests failed with it ("People in the scans").
  o.sensor.short_beyond = 0.3;
  o.global_short_beyond = 0;
  // Tracking weighs on a sharper normal term than the seed's 0.5 m: the laser's noise is
  // 5 cm, and 0.5 m left a cloud 0.2 m wide among people with few walls in view. 0.35 m:
  // 30 people, 14 drives of 300 m, mean RMS 0.067 -> 0.056 m, 1 000 m 0.128 -> 0.082 m;
  // 0.25 m jumped by up to 0.55 m on some drives ("A sharper sensor model for tracking").
  // The global phase keeps 0.5 m.
  o.tracking_sigma_m = 0.35;
  // KLD's floor while tracking (where the preset is adaptive, and in SimRobot, which
  // tracks adaptively with every preset); the global phase's stays KldOptions' 500. Among
  // 30 people 1 000 tracked better (GDC1 0.116 -> 0.090 m), but after the global search
  // it bought nothing and took the campus's p95 from 0.88 to 1.23 s ("A tracking cloud
  // of 1 000").
  o.tracking_min_particles = 1000;
  // The searches leave out returns standing in front of the map (foreground.h: people):
  // in the open each cost the truth the likelihood field's floor, and among 10 people the
  // truth was not among the candidates. fast's GDC1 50 -> 68 % (docs/localization.md,
  // "People left out of the search"); this preset's 20 trials of seed 7777, right answer
  // GDC1 35 -> 50 %, campus 60 -> 75 % ("The search preset tracks among people").
  o.search_drops_foreground = true;
  return o;
}

ParticleFilterOptions ParticleFilterOptions::fast_search() {
  ParticleFilterOptions o = robust_search();
  o.defer_look_around = true;   // one search, at the end of the look around
  o.search.coarse = 4;          // the same candidates, fewer blocks bounded
  o.search_candidates = 500;    // K: the truth's place ranks far ahead on seven stitched scans
  o.search_clusters = 100;
  o.search_particles = 1000;    // 10 per cluster instead of 30
  o.history_beam_stride = 3;    // the six earlier scans weigh the searched cloud on 44 beams each
  // The flat short term (global_short_beyond below) lets a wrong place on open ground call
  // the far walls people: the search's rerank and the weighing of its cloud grant it only
  // to foreground beams (docs/localization.md, "Short only in front"; campus 80.5 -> 87 %).
  o.search_short_only_foreground = true;
  o.adaptive = true;            // KLD: the collapsed cloud shrinks towards kld.min_particles
  // Tracking's floor of 1 000 particles, sharper sigma_m (0.35 m) and flat short term
  // (0.3 m), and the searches that leave people out, come from robust_search().
  // Six annealing stages instead of three: the searched cloud is weighed on seven scans
  // at once, and three stages at ESS 30 % left part of them unapplied, so look-alike
  // places were still heavy after the three steps driven (docs/localization.md, "Six
  // annealing stages").
  o.tempering_stages = 6;
  // Each stage after a scan's first jitters less (0.7^s of the capped jitter): with the
  // same at all six, a cloud of places far apart walked about 0.5 m per scan, and a
  // sharp, correct place lost to a flat wrong one (docs/localization.md, "Annealing's
  // diffusion shrinking by stage": the campus gained on three seeds, 94.0 -> 95.0 % on
  // the fresh one).
  o.roughening_stage_decay = 0.7;
  // The global phase takes the flat short term from 0.5 m (robust_search(): none), since
  // the search's rerank grants it to people only. Among 10 people 0.3 gave 156 of 200
  // trials the right answer where 0.5 gives 164, and 16 wrong poses where 0.5 gives 10;
  // without people the same within a trial ("The global phase from 0.5 m").
  o.global_short_beyond = 0.5;
  // Left as they were (docs/localization.md, "The search's misses on the campus
  // (2026-12-05)"): turn_in_place_sds 3 and roughening_max_xy 0.05 each saved campus misses
  // of seed 5151 but not on a fresh seed (7373: campus 94.0 -> 93.5 and 92.0 %), and the
  // cap gave more wrong poses among people.
  return o;
}

ParticleFilter::ParticleFilter(const Map& map, ParticleFilterOptions options)
    : ParticleFilter(map, std::shared_ptr<const RayCaster>(make_fast_ray_caster(map, options.laser)), options) {}

ParticleFilter::ParticleFilter(const Map& map, std::shared_ptr<const RayCaster> caster, ParticleFilterOptions options)
    : options_(options),
      beams_(evenly_spread_angles(options.beams, options.fov)),
      sensor_(options.tracking_sensor()),
      global_sensor_(global_sensor_options(options)),
      search_sensor_(search_sensor_options(options)),
      motion_(options.motion),
      compass_(options.compass_half_width),
      rng_(seeded(options.seed, 0xFFFFFFFFu)) {
  if (options.particles == 0) throw std::invalid_argument("ParticleFilterOptions.particles: expected > 0");
  if (options.beams <= 0) throw std::invalid_argument("ParticleFilterOptions.beams: expected > 0");
  if (!(options.roughening_stage_decay >= 0 && options.roughening_stage_decay <= 1))
    throw std::invalid_argument("ParticleFilterOptions.roughening_stage_decay: expected in [0, 1], got " +
                                std::to_string(options.roughening_stage_decay));
  options_.threads = std::max(1, options.threads);
  for (int k = 0; k < options_.threads; ++k) chunk_rngs_.push_back(seeded(options.seed, k));
  set_map(map, std::move(caster));
}

void ParticleFilter::set_map(const Map& map) { set_map(map, std::shared_ptr<const RayCaster>(make_fast_ray_caster(map, options_.laser))); }

void ParticleFilter::set_map(const Map& map, std::shared_ptr<const RayCaster> caster) {
  if (!caster) throw std::invalid_argument("ParticleFilter::set_map: caster: expected non-null");
  caster_ = std::move(caster);
  free_space_ = std::make_unique<FreeSpace>(map);
  map_ = map;
  search_.reset();  // built again on the new map when needed
}

void ParticleFilter::init_global(std::optional<double> compass) {
  const size_t n = std::max(options_.particles,
                            static_cast<size_t>(std::max(0.0, options_.global_density) * free_space_->area()));
  poses_.resize(n);
  std::uniform_real_distribution<double> any_heading(-kPi, kPi);
  for (Pose& p : poses_) {
    const Point q = free_space_->sample(rng_);
    p = {q.x, q.y, compass ? compass_.sample(*compass, rng_) : any_heading(rng_)};
  }
  weights_.assign(n, 1.0 / n);
  global_phase_ = options_.global_search && compass;
  init_compass_ = compass;
  searches_ = 0;
  searched_scans_ = 0;
  looking_around_ = true;
  from_global_ = true;
  since_global_ = 0;
  settled_.clear();
  since_scan_ = {};
  history_.clear();
  recent_.clear();
  rivals_.clear();
  since_recent_ = {};
}

bool ParticleFilter::turned_in_place(const Odometry& u) const {
  const double by_turn = std::sqrt(std::max(0.0, options_.motion.alpha4)) * std::fabs(u.dtheta);
  return motion_.decompose(u).trans < options_.turn_in_place + std::max(0.0, options_.turn_in_place_sds) * by_turn;
}

Odometry ParticleFilter::stitching_step(const Scan& before, const Scan& after) const {
  Odometry u = after.since_previous;
  const OdometryDecomposition d = motion_.decompose(u);
  double turn = u.dtheta, var = std::max(d.sd_rot1 * d.sd_rot1 + d.sd_rot2 * d.sd_rot2, 1e-12);
  // Odometry's error grows with every turn; two compass readings bound the turn within
  // the difference of two errors uniform in +-half width (variance 2 hw^2 / 3).
  if (before.compass && after.compass) {
    const double hw = compass_.half_width(), var_c = 2 * hw * hw / 3;
    const double by_compass = angle_diff(*after.compass, *before.compass);
    turn = normalize_angle(turn + var / (var + var_c) * angle_diff(by_compass, turn));
    var = var * var_c / (var + var_c);
  }
  // A turn in place (a look around): where the two scans overlap they tell it better.
  if (turned_in_place(u))
    turn = register_turn(before.ranges, after.ranges, beams_, options_.laser.rmax, turn, std::sqrt(var));
  // The displacement, small in place, turned with the heading (odometry's frame).
  u.dtheta = turn;
  return u;
}

const GlobalSearch& ParticleFilter::global_search() {
  if (!search_) {
    GlobalSearchOptions so = options_.search;
    so.field.margin = options_.laser.rmax;
    so.field.laser_height = options_.laser.laser_height;
    so.threads = options_.threads;
    search_ = std::make_shared<GlobalSearch>(map_, so);
  }
  return *search_;
}

std::vector<uint8_t> ParticleFilter::foreground_of(const std::vector<double>& ranges) const {
  // Only where an option reads it: the searches read the global phase's scans (and the
  // recent ones when settling), the sensor model every scan. Tracking with `fast` skips it.
  const bool searched = (options_.search_drops_foreground || options_.search_short_only_foreground) &&
                        (global_phase_ || options_.settle_after > 0);
  if (!searched && !options_.sensor.short_only_foreground) return {};
  return foreground_returns(ranges, beams_, options_.laser.rmax, options_.foreground);
}

StitchedScan ParticleFilter::stitch(const std::vector<Scan>& scans, size_t max_points) const {
  std::vector<const std::vector<double>*> ranges;
  std::vector<Odometry> odometry;
  std::vector<std::vector<double>> kept;  // the scans without their foreground
  if (options_.search_drops_foreground) {
    for (const Scan& scan : scans) {
      kept.push_back(scan.ranges);
      for (size_t j = 0; j < scan.foreground.size(); ++j)
        if (scan.foreground[j]) kept.back()[j] = options_.laser.rmax;  // as no return
    }
  }
  for (size_t k = 0; k < scans.size(); ++k) {
    ranges.push_back(kept.empty() ? &scans[k].ranges : &kept[k]);
    odometry.push_back(k > 0 ? stitching_step(scans[k - 1], scans[k]) : scans[k].since_previous);
  }
  return stitch_scans(ranges, odometry, beams_, options_.laser.rmax, max_points);
}

bool ParticleFilter::reseed_from_search(double compass) {
  global_search();
  const StitchedScan stitched = stitch(history_, options_.search_points);
  if (stitched.ranges.empty()) return false;
  const std::vector<Pose>& at = stitched.poses;
  std::vector<Candidate> found = search_->search(stitched.ranges, stitched.angles, std::numeric_limits<double>::infinity(), compass,
                                                 compass_.half_width(), options_.search_candidates);
  if (found.empty()) return false;
  // Ranked again by the filter's own sensor model on cast rays, every scan at its pose:
  // the likelihood field does not see through walls, eq. (4)-(5) do.
  parallel_for(options_.threads, found.size(), [&](int, size_t begin, size_t end) {
    std::vector<double> synthetic(beams_.size());
    for (size_t i = begin; i < end; ++i) {
      double ll = 0;
      for (size_t k = 0; k < history_.size(); ++k) {
        const Pose p = compose(found[i].pose, {at[k].x, at[k].y, at[k].theta});
        caster_->cast_scan(p.point(), p.theta, beams_, synthetic.data());
        ll += search_sensor_.log_weight(history_[k].ranges.data(), synthetic.data(), beams_.size(), history_[k].in_front());
      }
      found[i].score = ll;
    }
  });
  std::stable_sort(found.begin(), found.end(), [](const Candidate& l, const Candidate& r) { return l.score > r.score; });
  const size_t clusters = std::clamp<size_t>(options_.search_clusters, 1, found.size());
  const size_t n = options_.search_particles > 0 ? options_.search_particles : options_.particles;
  poses_.resize(n);
  std::normal_distribution<double> n01(0.0, 1.0);
  for (size_t i = 0; i < n; ++i) {
    const Pose& p = found[i % clusters].pose;
    poses_[i] = {p.x + options_.search_sd_xy * n01(rng_), p.y + options_.search_sd_xy * n01(rng_),
                 normalize_angle(p.theta + options_.search_sd_theta * n01(rng_))};
  }
  weights_.assign(n, 1.0 / n);
  keep_rivals(found, static_cast<double>(history_.size() * beams_.size()));
  candidates_ = std::move(found);
  searched_at_ = at;
  return true;
}

void ParticleFilter::keep_rivals(const std::vector<Candidate>& ranked, double beams) {
  rivals_.clear();
  const AmbiguityOptions& o = options_.ambiguity;
  if (!o.rivals || ranked.empty()) return;
  const double floor = ranked.front().score - o.rival_search_margin_per_beam * beams;
  for (const Candidate& c : ranked) {
    if (rivals_.size() >= o.max_rivals || c.score < floor) break;
    if (std::all_of(rivals_.begin(), rivals_.end(), [&](const Pose& r) { return distance(r, c.pose) > o.min_separation; }))
      rivals_.push_back(c.pose);
  }
}

void ParticleFilter::settle(double compass) {
  if (recent_.empty()) return;
  const StitchedScan stitched = stitch(recent_, options_.settle_points);
  if (stitched.ranges.empty()) return;
  std::vector<Candidate> found = global_search().search(stitched.ranges, stitched.angles,
                                                        std::numeric_limits<double>::infinity(), compass,
                                                        compass_.half_width(), options_.search_candidates);
  // The cloud's own places compete with the search's (its grid may fall between them).
  for (const Pose& p : find_ambiguity(poses_, weights_, options_.ambiguity).places) found.push_back({p, 0});
  if (found.empty()) return;
  // Each scan's pose from the latest, as stitched (recent_offsets() would stitch again).
  std::vector<Odometry> offsets;
  for (const Pose& p : stitched.poses) offsets.push_back({p.x, p.y, p.theta});
  const auto score_with = [&](std::vector<double>& synthetic, const Pose& place) {
    return recent_log_likelihood(place, offsets, synthetic);
  };
  parallel_for(options_.threads, found.size(), [&](int, size_t begin, size_t end) {
    std::vector<double> synthetic;
    for (size_t i = begin; i < end; ++i) found[i].score = score_with(synthetic, found[i].pose);
  });
  std::stable_sort(found.begin(), found.end(), [](const Candidate& l, const Candidate& r) { return l.score > r.score; });
  // The best distinct places, each refined to its own best pose.
  const double separation = options_.ambiguity.min_separation;
  const auto distinct = [&](const std::vector<Candidate>& from, size_t most) {
    std::vector<Candidate> taken;
    for (const Candidate& c : from) {
      if (taken.size() >= most) break;
      if (std::none_of(taken.begin(), taken.end(), [&](const Candidate& t) { return distance(t.pose, c.pose) <= separation; }))
        taken.push_back(c);
    }
    return taken;
  };
  std::vector<Candidate> places = distinct(found, std::max<size_t>(1, options_.settle_places));
  parallel_for(options_.threads, places.size(), [&](int, size_t begin, size_t end) {
    std::vector<double> synthetic;
    for (size_t i = begin; i < end; ++i) {
      const RefinedPlace r = refine_place(places[i].pose, [&](const Pose& p) { return score_with(synthetic, p); });
      places[i] = {r.pose, r.score};
    }
  });
  std::stable_sort(places.begin(), places.end(), [](const Candidate& l, const Candidate& r) { return l.score > r.score; });
  places = distinct(places, std::max<size_t>(1, options_.ambiguity.max_places));
  settled_ = places;
  // Places within the ambiguity margin of the best (per beam) share the cloud.
  const double beams = static_cast<double>(recent_.size() * beams_.size());
  const double floor = places.front().score - options_.ambiguity.margin_per_beam * beams;
  while (places.back().score < floor) places.pop_back();
  const size_t n = options_.search_particles > 0 ? options_.search_particles : options_.particles;
  poses_.resize(n);
  std::normal_distribution<double> n01(0.0, 1.0);
  for (size_t i = 0; i < n; ++i) {
    const Pose& p = places[i % places.size()].pose;
    poses_[i] = {p.x + options_.settle_sd_xy * n01(rng_), p.y + options_.settle_sd_xy * n01(rng_),
                 normalize_angle(p.theta + options_.settle_sd_theta * n01(rng_))};
  }
  weights_.assign(n, 1.0 / n);
}

void ParticleFilter::init_pose(const Pose& pose, double sd_xy, double sd_theta) {
  const size_t n = options_.particles;
  poses_.resize(n);
  global_phase_ = false;
  from_global_ = false;
  recent_.clear();
  rivals_.clear();
  since_recent_ = {};
  std::normal_distribution<double> n01(0.0, 1.0);
  for (Pose& p : poses_)
    p = {pose.x + sd_xy * n01(rng_), pose.y + sd_xy * n01(rng_), normalize_angle(pose.theta + sd_theta * n01(rng_))};
  weights_.assign(n, 1.0 / n);
}

void ParticleFilter::set_particles(std::vector<Pose> poses, std::vector<double> weights) {
  double sum = 0;
  for (double w : weights) sum += w >= 0 ? w : std::numeric_limits<double>::quiet_NaN();
  if (poses.empty() || poses.size() != weights.size() || !(sum > 0))
    throw std::invalid_argument("ParticleFilter::set_particles: expected as many weights >= 0 as poses, some > 0");
  for (double& w : weights) w /= sum;
  poses_ = std::move(poses);
  weights_ = std::move(weights);
  global_phase_ = false;
  from_global_ = false;
  rivals_.clear();
}

void ParticleFilter::predict(const Odometry& odometry) {
  {
    const Pose p = compose(compose(Pose{}, since_recent_), odometry);
    since_recent_ = {p.x, p.y, p.theta};
  }
  if (global_phase_) {  // the stitched scans need the odometry between them
    const Pose p = compose(compose(Pose{}, since_scan_), odometry);
    since_scan_ = {p.x, p.y, p.theta};
  }
  parallel_for(options_.threads, poses_.size(), [&](int k, size_t begin, size_t end) {
    std::mt19937_64& rng = chunk_rngs_[k];
    for (size_t i = begin; i < end; ++i) poses_[i] = motion_.sample(poses_[i], odometry, rng);
  });
  for (Pose& r : rivals_) r = compose(r, odometry);  // as measured: the verdict refines them
}

void ParticleFilter::update(const std::vector<double>& ranges, std::optional<double> compass) {
  if (ranges.size() != beams_.size())
    throw std::invalid_argument("ParticleFilter::update: ranges: expected " + std::to_string(beams_.size()) +
                                " beams, got " + std::to_string(ranges.size()));
  correct(ranges, compass, foreground_of(ranges));
}

void ParticleFilter::update(const std::vector<double>& ranges, std::optional<double> compass,
                            const std::vector<uint8_t>& foreground) {
  if (ranges.size() != beams_.size() || foreground.size() != beams_.size())
    throw std::invalid_argument("ParticleFilter::update: expected " + std::to_string(beams_.size()) +
                                " beams, got " + std::to_string(ranges.size()) + " ranges and " +
                                std::to_string(foreground.size()) + " foreground flags");
  correct(ranges, compass, foreground);
}

void ParticleFilter::correct(const std::vector<double>& ranges, std::optional<double> compass,
                             std::vector<uint8_t> front) {
  if (poses_.empty()) throw std::logic_error("ParticleFilter::update: no particles (call init_global or init_pose)");
  searched_at_.clear();
  if (from_global_) ++since_global_;
  last_foreground_ = front;
  if (options_.ambiguity.scans > 0) {
    if (recent_.size() >= options_.ambiguity.scans) recent_.erase(recent_.begin());
    recent_.push_back({since_recent_, ranges, compass, front});
    since_recent_ = {};
  }
  if (global_phase_) {
    // Whether the robot is looking around is known from the motion since the last scan.
    if (!history_.empty() && !turned_in_place(since_scan_)) looking_around_ = false;
    const size_t searches = std::max<size_t>(1, options_.search_updates);
    const bool unsearched = history_.size() > searched_scans_;  // scans a deferred look around kept
    if (searches_ >= searches && !looking_around_ && !unsearched) {
      global_phase_ = false;
    } else {
      history_.push_back({since_scan_, ranges, compass, front});
      since_scan_ = {};
      // The look around ends at its last turn, or when the robot drives before that.
      const bool last = history_.size() >= searches + options_.look_around_searches ||
                        (!looking_around_ && (options_.defer_look_around || searches_ >= searches));
      if (options_.defer_look_around && !last) {
        ++updates_;  // kept for the search at the end of the look around; the cloud waits
        return;
      }
      reseed_from_search(compass.value_or(*init_compass_));
      searched_scans_ = history_.size();
      ++searches_;
      if (last) global_phase_ = false;
    }
  }
  const bool use_compass = compass && options_.compass_weight;
  const RayCaster& caster = *caster_;
  // Annealing (tempering_stages > 1): what a stage's phi leaves of the scan's exponent
  // is applied by the next stage, after resampling and roughening, on new rays.
  double budget = 1;
  const int stages = std::max(1, options_.tempering_stages);
  for (int stage = 0; stage < stages && budget > 1e-9; ++stage) {
    const double jitter = std::pow(options_.roughening_stage_decay, stage);
    // Weights kept from an earlier update may already be below the tempering target.
    if (options_.tempering_ess > 0 && effective_sample_size() < options_.tempering_ess * poses_.size()) {
      resample();
      roughen(jitter);
    }
    // The earlier scans of a look around, every history_beam_stride-th beam (the latest whole).
    std::vector<std::vector<double>> earlier_ranges, earlier_beams;
    std::vector<std::vector<uint8_t>> earlier_front;
    const size_t stride = std::max<size_t>(1, options_.history_beam_stride);
    for (size_t k = 0; k < searched_at_.size(); ++k) {
      earlier_ranges.emplace_back();
      earlier_beams.emplace_back();
      earlier_front.emplace_back();
      const bool latest = k + 1 == searched_at_.size();
      for (size_t j = 0; j < beams_.size(); j += latest ? 1 : stride) {
        earlier_ranges.back().push_back(history_[k].ranges[j]);
        earlier_beams.back().push_back(beams_[j]);
        if (!history_[k].foreground.empty()) earlier_front.back().push_back(history_[k].foreground[j]);
      }
    }
    const uint8_t* latest_front = front.empty() ? nullptr : front.data();
    const SensorModel& model = weighing_sensor();  // one phase for the whole update
    log_likelihood_.resize(poses_.size());
    parallel_for(options_.threads, poses_.size(), [&](int, size_t begin, size_t end) {
      std::vector<double> synthetic(beams_.size());
      for (size_t i = begin; i < end; ++i) {
        const Pose& p = poses_[i];
        double ll = 0;
        if (searched_at_.empty()) {
          caster.cast_scan(p.point(), p.theta, beams_, synthetic.data());
          ll = model.log_weight(ranges.data(), synthetic.data(), beams_.size(), latest_front);
        }
        // A fresh cloud from a search has not yet seen the scans before this one.
        for (size_t k = 0; k < searched_at_.size(); ++k) {
          const Pose q = compose(p, {searched_at_[k].x, searched_at_[k].y, searched_at_[k].theta});
          caster.cast_scan(q.point(), q.theta, earlier_beams[k], synthetic.data());
          ll += search_sensor_.log_weight(earlier_ranges[k].data(), synthetic.data(), earlier_beams[k].size(),
                                   earlier_front[k].empty() ? nullptr : earlier_front[k].data());
        }
        if (use_compass) ll += compass_.log_likelihood(p.theta, *compass);
        log_likelihood_[i] = ll;
      }
    });
    budget -= weigh(budget, jitter);
  }
  last_phi_ = 1 - budget;
  ++updates_;
  if (!global_phase_) history_.clear();
  const std::optional<double> heading = compass ? compass : init_compass_;
  if (from_global_ && options_.settle_after > 0 && since_global_ == options_.settle_after && heading) settle(*heading);
  drop_ruled_out_rivals();
}

void ParticleFilter::drop_ruled_out_rivals() {
  const AmbiguityOptions& o = options_.ambiguity;
  if (!o.drop_ruled_out_rivals || rivals_.empty() || o.scans == 0 || recent_.size() < o.scans) return;
  const PoseEstimate e = estimate();
  if (!e.converged) return;  // the reference must be one place
  const auto scans = residual_scans();
  const ResidualJudge judge(o, stitched_residual(scans), o.register_scans ? registered_residual(scans)
                                                                          : RegisteredResidual{});
  const ResidualJudge::Reference reference = judge.reference_at(e.pose);
  std::erase_if(rivals_, [&](const Pose& r) {
    return distance(r, e.pose) > o.min_separation && judge.ruled_out(r, reference, o.rival_drop_margin_z2);
  });
}

double ParticleFilter::weigh(double most, double roughening) {
  const double phi = choose_tempering(log_likelihood_, most);
  // seed 000 eq. (6): w(t) = w(t-1) * 1 / sum_j 1 / L(delta_j), as logarithms (to the
  // power phi when tempered).
  for (size_t i = 0; i < poses_.size(); ++i) weights_[i] = std::log(weights_[i]) + phi * log_likelihood_[i];
  normalize_weights();
  // A tempered stage stopped at the target ESS: resample before the next one.
  if (phi < most || effective_sample_size() < options_.resample_threshold * poses_.size()) {
    resample();
    roughen(roughening);
  }
  return phi;
}

double ParticleFilter::choose_tempering(const std::vector<double>& ll, double most) const {
  if (!(options_.tempering_ess > 0)) return most;
  const size_t n = poses_.size();
  // Effective sample size of w(t-1) * L^phi.
  std::vector<double> lw(n);
  const auto ess = [&](double phi) {
    double top = -std::numeric_limits<double>::infinity();
    for (size_t i = 0; i < n; ++i) {
      lw[i] = std::log(weights_[i]) + phi * ll[i];
      if (!std::isnan(lw[i])) top = std::max(top, lw[i]);
    }
    if (std::isinf(top)) return 0.0;
    double s = 0, s2 = 0;
    for (double v : lw) {
      const double w = std::isnan(v) ? 0.0 : std::exp(v - top);
      s += w;
      s2 += w * w;
    }
    return s * s / s2;
  };
  const double target = options_.tempering_ess * static_cast<double>(n);
  if (ess(most) >= target || ess(0.0) < target) return most;
  double lo = 0, hi = most;  // ess(lo) >= target > ess(hi)
  for (int k = 0; k < 30; ++k) {
    const double mid = (lo + hi) / 2;
    (ess(mid) >= target ? lo : hi) = mid;
  }
  return lo;
}

double ParticleFilter::effective_sample_size() const {
  double sum_sq = 0;
  for (double w : weights_) sum_sq += w * w;
  return 1 / sum_sq;
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
  const KldOptions kld = from_global_ ? options_.kld : options_.tracking_kld();
  const std::vector<size_t> idx = options_.adaptive ? kld_resample(poses_, weights_, kld, rng_)
                                                    : low_variance_resample(weights_, options_.particles, rng_);
  std::vector<Pose> next(idx.size());
  for (size_t m = 0; m < idx.size(); ++m) next[m] = poses_[idx[m]];
  poses_ = std::move(next);
  weights_.assign(poses_.size(), 1.0 / poses_.size());
  ++resamplings_;
}

void ParticleFilter::roughen(double factor) {
  if (!(options_.roughening > 0) || !(factor > 0) || poses_.size() < 2) return;
  // Per-dimension standard deviations of the (equally weighted) resampled cloud.
  const double n = static_cast<double>(poses_.size());
  const WeightedMean m = weighted_mean(poses_, weights_, [](size_t) { return true; });
  const Eigen::Matrix2d cov = position_scatter(poses_, m.pose, [](size_t) { return 1.0; }) / n;
  const double r = std::min(1.0, std::hypot(m.cos_sum, m.sin_sum) / m.weight);
  const double spread_theta = r > 0 ? std::sqrt(-2 * std::log(r)) : kPi;
  const double scale = options_.roughening * std::pow(n, -1.0 / 3.0);
  const double sx = factor * std::min(options_.roughening_max_xy, scale * std::sqrt(cov(0, 0)));
  const double sy = factor * std::min(options_.roughening_max_xy, scale * std::sqrt(cov(1, 1)));
  const double st = factor * std::min(options_.roughening_max_theta, scale * spread_theta);
  parallel_for(options_.threads, poses_.size(), [&](int k, size_t begin, size_t end) {
    std::mt19937_64& rng = chunk_rngs_[k];
    std::normal_distribution<double> n01(0.0, 1.0);
    for (size_t i = begin; i < end; ++i) {
      Pose& p = poses_[i];
      p = {p.x + sx * n01(rng), p.y + sy * n01(rng), normalize_angle(p.theta + st * n01(rng))};
    }
  });
}

std::vector<Odometry> ParticleFilter::recent_offsets() const {
  // Each recent scan from a place: at the place composed with the motion from the latest
  // scan back to that one, stitched as for the global search (a look around's turns
  // from odometry alone would misplace its earlier scans by degrees).
  std::vector<Pose> at{Pose{}};
  for (size_t k = 1; k < recent_.size(); ++k) at.push_back(compose(at.back(), stitching_step(recent_[k - 1], recent_[k])));
  std::vector<Odometry> back;
  for (const Pose& p : at) back.push_back(between(at.back(), p));
  return back;
}

double ParticleFilter::recent_log_likelihood(const Pose& place, const std::vector<Odometry>& offsets,
                                             std::vector<double>& synthetic) const {
  double ll = 0;
  synthetic.resize(beams_.size());
  for (size_t k = 0; k < recent_.size() && k < offsets.size(); ++k) {
    const Pose p = compose(place, offsets[k]);
    caster_->cast_scan(p.point(), p.theta, beams_, synthetic.data());
    ll += weighing_sensor().log_weight(recent_[k].ranges.data(), synthetic.data(), beams_.size(), recent_[k].in_front());
  }
  return ll;
}

double ParticleFilter::recent_log_likelihood(const Pose& place) const {
  std::vector<double> synthetic;
  return recent_log_likelihood(place, recent_offsets(), synthetic);
}

PlaceScore ParticleFilter::recent_fit() const {
  const double beams = static_cast<double>(std::max<size_t>(1, recent_.size() * beams_.size()));
  auto synthetic = std::make_shared<std::vector<double>>();
  return [this, offsets = recent_offsets(), synthetic, beams](const Pose& place) {
    return recent_log_likelihood(place, offsets, *synthetic) / beams;
  };
}

// The recent scans' residual (AmbiguityOptions::rivals), shared by the scores made from
// it, which any thread may call.
struct ParticleFilter::ResidualScans {
  const RayCaster* caster = nullptr;
  const std::vector<double>* beams = nullptr;
  std::vector<const std::vector<double>*> ranges;
  std::vector<Odometry> stitched;  // each scan's pose from the latest (recent_offsets())
  std::vector<std::vector<uint8_t>> kept;
  double kept_beams = 0;
  double sigma = 0, cap = 0;
  // Scan k's summed residual from a pose (from any thread).
  double scan(size_t k, const Pose& p) const {
    thread_local std::vector<double> synthetic;
    synthetic.resize(beams->size());
    caster->cast_scan(p.point(), p.theta, *beams, synthetic.data());
    double sum = 0;
    for (size_t j = 0; j < beams->size(); ++j) {
      if (!kept[k][j]) continue;
      const double z = ((*ranges[k])[j] - synthetic[j]) / sigma;
      sum += std::min(z * z, cap);
    }
    return sum;
  }
  // The negated mean residual, each scan at the place composed with its offset.
  double place(const Pose& at, const std::vector<Odometry>& offsets) const {
    double sum = 0;
    for (size_t k = 0; k < ranges.size() && k < offsets.size(); ++k) sum += scan(k, compose(at, offsets[k]));
    return -sum / kept_beams;
  }
};

std::shared_ptr<const ParticleFilter::ResidualScans> ParticleFilter::residual_scans() const {
  const AmbiguityOptions& o = options_.ambiguity;
  auto r = std::make_shared<ResidualScans>();
  r->stitched = recent_offsets();
  r->caster = caster_.get();
  r->beams = &beams_;
  r->sigma = o.rival_sigma;
  r->cap = o.rival_max_z2;
  // Returns in front of the map (people, foreground.h) are left out: every place pays the
  // cap on them alike, and counted they would dilute the difference between places.
  // (registered_residual() takes back those its place explains.)
  for (const Scan& scan : recent_) {
    const std::vector<uint8_t> front =
        scan.foreground.empty() ? foreground_returns(scan.ranges, beams_, options_.laser.rmax, options_.foreground)
                                : scan.foreground;
    r->ranges.push_back(&scan.ranges);
    std::vector<uint8_t>& keep = r->kept.emplace_back(front.size());
    for (size_t j = 0; j < front.size(); ++j) {
      keep[j] = !front[j];
      r->kept_beams += keep[j];
    }
  }
  r->kept_beams = std::max(1.0, r->kept_beams);
  return r;
}

PlaceScore ParticleFilter::recent_residual() const { return stitched_residual(residual_scans()); }

RegisteredResidual ParticleFilter::registered_residual() const { return registered_residual(residual_scans()); }

PlaceScore ParticleFilter::stitched_residual(std::shared_ptr<const ResidualScans> r) {
  return [r](const Pose& place) { return r->place(place, r->stitched); };
}

RegisteredResidual ParticleFilter::registered_residual(std::shared_ptr<const ResidualScans> r) const {
  const AmbiguityOptions& o = options_.ambiguity;
  return [this, r, &o](const Pose& place) {
    const std::vector<Odometry>& stitched = r->stitched;
    // Each scan at its own best pose near where the stitching puts it, within the
    // window: the stitching's error (odometry's translation, a registered turn) costs
    // the right place more than the margin between places.
    RefineOptions window;
    window.step_xy = o.register_step_xy;
    window.step_theta = o.register_step_theta;
    window.min_step_xy = 0.003;
    window.min_step_theta = deg2rad(0.03);
    window.max_moves = o.register_moves;
    std::vector<Pose> poses(std::min(r->ranges.size(), stitched.size()));  // each scan's registered pose
    parallel_for(options_.threads, poses.size(), [&](int, size_t begin, size_t end) {
      for (size_t k = begin; k < end; ++k) {
        const Pose at = compose(place, stitched[k]);
        const auto bounded = [&](const Pose& p) {
          if (distance(p, at) > o.register_max_xy || std::fabs(angle_diff(p.theta, at.theta)) > o.register_max_theta)
            return -std::numeric_limits<double>::infinity();
          return -r->scan(k, p);
        };
        poses[k] = refine_place(at, bounded, window).pose;
      }
    });
    // Relative to the latest scan's registered pose: a place judged on these scans is
    // where that scan would have been taken.
    const Pose latest = poses.empty() ? place : poses.back();
    std::vector<Odometry> offsets;
    for (const Pose& p : poses) offsets.push_back(between(latest, p));
    // A narrow return foreground.h flags may be the map's (a pillar, a post): where the
    // place explains it, within 3 sigma, it is kept. Such returns are what tells a place
    // from one without them (a campus trial: 0.09 per beam between the truth and a place
    // 280 m away with them left out, 0.28 with them).
    auto judged = std::make_shared<ResidualScans>(*r);
    std::vector<double> cast(beams_.size());
    for (size_t k = 0; k < poses.size(); ++k) {
      const Pose& p = poses[k];
      caster_->cast_scan(p.point(), p.theta, beams_, cast.data());
      for (size_t j = 0; j < cast.size(); ++j)
        if (!judged->kept[k][j] && std::fabs((*judged->ranges[k])[j] - cast[j]) <= 3 * o.rival_sigma) {
          judged->kept[k][j] = 1;
          judged->kept_beams += 1;
        }
    }
    return RegisteredScans{
        latest, PlaceScore([judged, offsets = std::move(offsets)](const Pose& q) { return judged->place(q, offsets); })};
  };
}

Ambiguity ParticleFilter::ambiguity(AmbiguityRule rule) const {
  if (rule == AmbiguityRule::Weight || recent_.empty()) return find_ambiguity(poses_, weights_, options_.ambiguity);
  if (rivals_.empty() && !options_.ambiguity.candidates_by_residual)
    return find_ambiguity(poses_, weights_, options_.ambiguity, recent_fit());
  AmbiguityOptions o = options_.ambiguity;
  o.threads = options_.threads;  // the residuals cast from any thread
  const auto scans = residual_scans();  // one stitching and one foreground pass for both scores
  // The move rests on differences of a few hundredths per beam between registered fits;
  // among people those differ by more (AmbiguityOptions::move_max_foreground).
  size_t beams = 0;
  for (const auto& kept : scans->kept) beams += kept.size();
  if (beams > 0 && 1 - scans->kept_beams / static_cast<double>(beams) > o.move_max_foreground)
    o.register_moves_place = false;
  return find_ambiguity(poses_, weights_, o, recent_fit(), rivals_, stitched_residual(scans),
                        o.register_scans ? registered_residual(scans) : RegisteredResidual{});
}

PoseEstimate ParticleFilter::estimate() const {
  PoseEstimate e;
  e.particles = poses_.size();
  if (poses_.empty()) return e;
  const WeightedMean all = weighted_mean(poses_, weights_, [](size_t) { return true; });
  double sum_sq = 0;
  for (double w : weights_) sum_sq += w * w;
  const double r = std::min(1.0, std::hypot(all.cos_sum, all.sin_sum) / all.weight);
  e.mean = all.pose;
  e.covariance = position_scatter(poses_, all.pose, [&](size_t i) { return weights_[i]; }) / all.weight;
  e.spread_xy = std::sqrt(e.covariance.trace());
  e.spread_theta = r > 0 ? std::sqrt(-2 * std::log(r)) : kPi;
  e.n_eff = all.weight * all.weight / sum_sq;
  e.converged = e.spread_xy < options_.converged_xy && e.spread_theta < options_.converged_theta;

  // The heaviest 3 x 3 block of cells.
  const double inv = 1 / options_.cluster_cell;
  std::vector<std::pair<int64_t, int64_t>> cell(poses_.size());
  std::unordered_map<uint64_t, double> mass;
  for (size_t i = 0; i < poses_.size(); ++i) {
    cell[i] = {static_cast<int64_t>(std::floor(poses_[i].x * inv)), static_cast<int64_t>(std::floor(poses_[i].y * inv))};
    mass[cell_key(cell[i].first, cell[i].second)] += weights_[i];
  }
  double best = -1;
  std::pair<int64_t, int64_t> centre{};
  for (size_t i = 0; i < poses_.size(); ++i) {
    double m = 0;
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy) {
        const auto it = mass.find(cell_key(cell[i].first + dx, cell[i].second + dy));
        if (it != mass.end()) m += it->second;
      }
    if (m > best) {
      best = m;
      centre = cell[i];
    }
  }
  const WeightedMean c = weighted_mean(poses_, weights_, [&](size_t i) {
    return std::abs(cell[i].first - centre.first) <= 1 && std::abs(cell[i].second - centre.second) <= 1;
  });
  e.pose = c.weight > 0 ? c.pose : all.pose;
  e.cluster_weight = c.weight / all.weight;
  return e;
}

}  // namespace fleetmap::localization
