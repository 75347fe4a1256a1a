#pragma once
// The particle filter of seed 000 section 4.1 (Fig. 4) for global localization and
// tracking on the segment map: initialise, then per laser scan predict (odometry),
// update (eq. 4-6 on synthetic rays) and resample.
//
//  * Global initialisation: NP particles (more with global_density, on a map larger than
//    the seed's) uniform over free space (free_space.h: the border minus closed
//    obstacles), headings from the compass prior (+-3 degrees).
//  * predict: each particle moves by its own draw of the odometry model (motion_model.h).
//  * update: each particle casts NL synthetic rays through the RayCaster (the fast
//    GridRayCaster unless one is given) and its weight is multiplied by eq. (6)
//    (sensor_model.h), optionally by the compass term; particles are split over
//    `threads` threads in fixed chunks.
//  * global search (off in the seed's options, global_search.h): after init_global with a
//    compass, the first search_updates updates (1 by default), and up to
//    look_around_searches more while the robot only turns in place (a look around),
//    replace the cloud before weighing it on every scan so far. The scans, stitched into
//    the current robot frame by odometry whose turns are corrected by the compass and,
//    in place, by the overlap of consecutive scans (stitched_scan.h,
//    turn_registration.h), are matched over every 0.1 m of free space and the compass's
//    headings on a likelihood field; the search_candidates best places are ranked again
//    by this filter's sensor model on cast rays (each scan at its pose: eq. 4-5 see the
//    walls a likelihood field sees through); the NP particles go around the
//    search_clusters best (N(place, search_sd_xy, search_sd_theta)) and the update goes
//    on as usual. Why: a uniform cloud leaves the truth's neighbourhood empty on a large
//    map (the seed's density, 0.6 per square metre, puts the nearest particle about
//    0.6 m from the truth; 6000 over the campus, 0.03 per square metre, about 3 m), and
//    the product of 131 beams tells a particle 0.5 m off from a wrong place poorly.
//  * tempering (off in the seed's options): when one scan would leave fewer than
//    tempering_ess * N particles effective, only its power phi < 1 is applied, the
//    largest that keeps them (adaptive tempering, Jasra et al. 2011); with
//    tempering_stages > 1 the rest of the exponent is applied after resampling, on new
//    rays (annealing, Deutscher et al. 2000). It keeps a global cloud from collapsing on
//    the first particle that happens to fit; a converged cloud takes every scan whole.
//  * settling (off in every preset, bench-localization --settle-after): after the
//    settle_after-th update since init_global, every recent scan is searched at once and
//    the cloud is replaced by the best places, refined (below, settle_after).
//  * resampling when the effective sample size falls below resample_threshold * N:
//    low-variance (NP kept), or KLD sampling when adaptive (tracking; the count follows
//    the spread of the cloud between kld.min_particles and kld.max_particles). Then
//    roughening (Gordon, Salmond & Smith 1993): each resampled particle is jittered by
//    N(0, K s N^(-1/3)) per dimension, s the cloud's standard deviation in it (capped),
//    so that copies of one particle do not stay identical while the robot stands still.
//  * estimate: weighted mean (circular mean for theta) and spread, the standard
//    deviations of position (sqrt(var x + var y)) and of heading (circular). While the
//    cloud still holds several hypotheses their mean lies between them, so the pose
//    reported is the weighted mean of the heaviest cluster (as Nav2's AMCL does): the
//    3 x 3 block of cluster_cell cells holding the most weight.
//
// Reproducible: every random draw comes from std::mt19937_64 generators seeded from
// `seed` (one per thread chunk, one for the sequential steps); the same seed, options,
// thread count and inputs give the same particles. The filter holds no clock.
#include <algorithm>
#include <cstdint>
#include <memory>
#include <optional>
#include <random>
#include <vector>

#include "client/localization/ambiguity.h"
#include "client/localization/compass_prior.h"
#include "client/localization/foreground.h"
#include "client/localization/free_space.h"
#include "client/localization/global_search.h"
#include "client/localization/motion_model.h"
#include "client/localization/pose.h"
#include "client/localization/resampling.h"
#include "client/localization/sensor_model.h"
#include "client/localization/stitched_scan.h"
#include "common/map/map.h"
#include "common/raycast/ray_caster.h"

namespace fleetmap::localization {

struct ParticleFilterOptions {
  size_t particles = 6000;            // NP (seed 000 section 4.1)
  int beams = 131;                    // NL
  double fov = kPi;                   // the NL beams spread evenly over 180 degrees
  RayCasterOptions laser{0.3, 15.0};  // hL and RMAX; RMAX is also the sensor model's
  SensorModelOptions sensor;          // alpha 1, beta 0.1, sigma_m 0.5 m, eq. (6)
  MotionNoise motion;
  double compass_half_width = deg2rad(3.0);
  bool compass_weight = true;         // weigh by the compass at each update given one
  // init_global draws max(NP, global_density * free area) particles; the first
  // resampling brings the set back to NP. The seed's 6000 over 100 m x 100 m are 0.6
  // per square metre; the campus (0.2 km2) at that density would be 128 000. 0: NP.
  double global_density = 0;
  double resample_threshold = 0.5;    // resample when N_eff < this * N (1: every update)
  double tempering_ess = 0;           // 0: no tempering (the seed)
  int tempering_stages = 1;
  double roughening = 0.2;            // K; 0 disables
  double roughening_max_xy = 0.2;     // metres: caps of the jitter's standard deviation,
  double roughening_max_theta = deg2rad(1.0);  // so far-apart hypotheses do not blur
  // (A cloud of places far apart always jitters by the caps, at each resampling: with
  // tempering several times per scan. A cap of 0.05 m kept the truth's sharp place on two
  // campus misses but not on a fresh seed: docs/localization.md, "The search's misses on
  // the campus (2026-12-05)".)
  // Annealing's diffusion shrinks layer by layer (Deutscher et al. 2000): at a scan's
  // s-th stage (from 0) the jitter, capped as above, is multiplied by
  // roughening_stage_decay^s. With 1, a cloud of places far apart walks about
  // sqrt(stages) x 0.2 m per scan, and a sharp, correct place loses to a flat wrong one
  // (docs/localization.md, "Annealing's diffusion shrinking by stage"; 0.7 in fast_search).
  double roughening_stage_decay = 1;
  // The sensor model's short_beyond while localizing globally, from init_global to the
  // next init_pose or set_particles: the search's rerank, the updates after it and the
  // verdict. Negative: sensor.short_beyond throughout.
  double global_short_beyond = -1;
  bool global_search = false;         // the global phase searches (above)
  GlobalSearchOptions search;         // its likelihood field; margin and hL set from laser
  size_t search_candidates = 2000;    // places the likelihood field keeps (M)
  size_t search_clusters = 200;       // of those, the best by cast rays that get particles
  size_t search_updates = 1;          // updates that search (bench: more while driving did not help)
  // Besides, while the robot has only turned in place since init_global (a look around),
  // up to this many more updates search again with every scan so far: a full turn shows
  // what one 180 degree scan does not (bench-localization --look-around).
  size_t look_around_searches = 6;
  // Whether the global phase's searches wait for the end of the look around (its last
  // turn, or the first step driven): the scans are kept and only that update searches, on
  // all of them. Without, every update of the look around searches, and each cloud is
  // thrown away by the next search. The updates before leave the cloud as initialised.
  bool defer_look_around = false;
  size_t search_particles = 0;        // particles spread over the clusters (0: NP)
  // Settling (off in every preset): at the end of the settle_after-th update since
  // init_global (with a compass), the scans since then (the last ambiguity.scans) are
  // searched at once, stitched as for the global search; the search's candidates and the
  // cloud's own places are ranked on cast rays over every scan, the settle_places best
  // distinct places refined (place_refinement.h), and the cloud replaced by particles
  // around each refined place within ambiguity.margin_per_beam of the best (one place,
  // or look-alikes the ambiguity verdict then reports). Why: after the look around and
  // a few steps the scans tell the places apart, but a tempered cloud has not yet
  // applied them all, and the heaviest block of it is not the place that explains them
  // best. Measured (docs/localization.md, "Settling on every scan"): fewer wrong poses,
  // more ambiguous verdicts, less success, three times the time: not in fast_search.
  // An update that a deferred look around keeps for its search (defer_look_around) does
  // not settle: with fast_search, whose look around is six updates, a settle_after
  // below 7 has no effect.
  size_t settle_after = 0;
  size_t settle_places = 10;
  size_t settle_points = 524;         // stitched points searched (4 NL)
  double settle_sd_xy = 0.03;         // metres: the spread around a refined place
  double settle_sd_theta = deg2rad(0.3);
  // A searched cloud is weighed on the earlier scans by every this-th beam (the latest
  // scan by all): 1 casts them all.
  size_t history_beam_stride = 1;
  size_t search_points = 262;         // at most this many stitched points (2 NL) searched
  // Whether the searches (global and settling) leave out returns standing in front of
  // the map (foreground.h: people): in the open, each costs the truth the field's floor.
  bool search_drops_foreground = false;
  // Whether the search's rerank and the weighing of its cloud on the kept scans let only
  // foreground beams stop short (SensorModelOptions::short_only_foreground); tracking
  // keeps the sensor options as they are.
  bool search_short_only_foreground = false;
  ForegroundOptions foreground;
  double turn_in_place = 0.05;        // metres: below, a step's turn comes from its scans
  // Besides, a step is a turn in place while its translation stays below turn_in_place plus
  // this many standard deviations of the translation the motion model gives its turn
  // (sqrt(alpha4) |dtheta|): odometry reports a few centimetres on a turn in place (the
  // simulated robot's 2.3 cm per 60 degrees: one turn in 60 over 5 cm ahead), and a look
  // around taken for driving ends at that turn, searched on the scans so far, its later
  // turns left to the motion model (docs/localization.md, "The search's misses on the
  // campus": 3 saved one miss of seed 5151 and changed one trial of 200 on a fresh seed,
  // for the worse; off in every preset). 0: turn_in_place alone.
  double turn_in_place_sds = 0;
  double search_sd_xy = 0.1;          // metres: spread of a cluster (the field's cell)
  double search_sd_theta = deg2rad(0.7);  // radians: about the search's heading step
  bool adaptive = false;              // KLD sampling instead of a fixed NP
  KldOptions kld;
  // KLD's floor from init_pose or set_particles on (tracking a known pose), where it is
  // above kld.min_particles (and up to kld.max_particles); the global phase keeps
  // kld.min_particles. Why apart: among 30 people 1 000 tracked better than 500, but after
  // the global search it bought nothing and cost a third of the time (docs/localization.md,
  // "A tracking cloud of 1 000"). 0: kld.min_particles throughout.
  size_t tracking_min_particles = 0;
  // The sensor model's sigma_m from init_pose or set_particles on (metres; not positive:
  // sensor.sigma_m throughout). Why apart: a known pose needs no tolerance for a wrong
  // one, and the global phase's search and annealing were measured on sensor.sigma_m.
  double tracking_sigma_m = -1;
  // What tracking runs with: kld with the tracking floor, and sigma_m.
  KldOptions tracking_kld() const {
    KldOptions k = kld;
    k.min_particles = std::min(std::max(k.min_particles, tracking_min_particles), k.max_particles);
    return k;
  }
  double tracking_sigma() const { return tracking_sigma_m > 0 ? tracking_sigma_m : sensor.sigma_m; }
  // The sensor model tracking weighs with: sensor, one RMAX (the laser's range is the
  // uniform term's width), and tracking_sigma().
  SensorModelOptions tracking_sensor() const;
  double cluster_cell = 1.0;              // metres, for PoseEstimate::pose
  double converged_xy = 0.5;              // metres of spread under which
  double converged_theta = deg2rad(5.0);  // and radians: PoseEstimate::converged
  AmbiguityOptions ambiguity;             // ParticleFilter::ambiguity
  int threads = 2;
  uint64_t seed = 1;

  // The seed's filter: the defaults above, eq. (5)-(6) as written.
  static ParticleFilterOptions seed_model() { return {}; }
  // What bench-localization found to localize globally on the real maps: the product of
  // the beams with a floor (gamma 0.1) instead of eq. (6), adaptive tempering (ESS 30 %,
  // 3 stages), and 0.3 particles per square metre at initialisation.
  static ParticleFilterOptions robust();
  // robust() whose global cloud comes from the global search instead of a uniform draw:
  // what fleetmap-robot and SimRobot use.
  static ParticleFilterOptions robust_search();
  // robust_search() within a second of computation (bench-localization --config
  // search,fast): the look around searches once, at its end, on every scan; fewer
  // candidates, clusters and particles; the searched cloud weighed on a third of the
  // earlier scans' beams; six annealing stages; KLD sampling once it has collapsed.
  static ParticleFilterOptions fast_search();
};

struct PoseEstimate {
  Pose pose;                // weighted mean of the heaviest cluster (below)
  Pose mean;                // weighted mean of every particle; theta the circular mean
  double cluster_weight = 0;  // the heaviest cluster's share of the weight
  double spread_xy = 0;     // metres: sqrt(weighted var x + var y), every particle
  // m^2: weighted covariance of x and y, every particle (what AMCL publishes with its pose).
  Eigen::Matrix2d covariance = Eigen::Matrix2d::Zero();
  double spread_theta = 0;  // radians: sqrt(-2 ln R), R the mean resultant length
  double n_eff = 0;         // 1 / sum w^2 of the normalized weights
  size_t particles = 0;
  bool converged = false;   // both spreads under the options' thresholds
};

class ParticleFilter {
 public:
  // Casts on a GridRayCaster built from the map (through the RayCaster interface).
  explicit ParticleFilter(const Map& map, ParticleFilterOptions options = {});
  // Casts on the given caster (tests, another implementation); map gives free space.
  ParticleFilter(const Map& map, std::shared_ptr<const RayCaster> caster, ParticleFilterOptions options);

  // A new map, e.g. a window around the robot (SPEC 5.4): a new RayCaster and free
  // space; the particles and their weights are kept.
  void set_map(const Map& map);
  void set_map(const Map& map, std::shared_ptr<const RayCaster> caster);

  // Global localization: NP particles (global_density) uniform over free space,
  // headings within the compass's +-half width of the reading, or uniform in (-pi, pi]
  // without one. With global_search and a compass, the next search_updates updates
  // search first (above).
  void init_global(std::optional<double> compass);
  // The search to use (shared between filters on the same map, e.g. trials); without
  // one, the filter builds its own at the first global search after set_map.
  void set_global_search(std::shared_ptr<const GlobalSearch> search) { search_ = std::move(search); }
  // Tracking from a known pose: NP particles from N(pose, diag(sd_xy, sd_xy, sd_theta)).
  void init_pose(const Pose& pose, double sd_xy, double sd_theta);
  // Any particle set (a saved state, a test's); weights are normalized here. Throws
  // std::invalid_argument when the sizes differ, the set is empty or no weight is > 0.
  void set_particles(std::vector<Pose> poses, std::vector<double> weights);

  // Prediction with the odometry measured since the last call.
  void predict(const Odometry& odometry);
  // Correction with a scan (ranges[j] along beam_angles()[j]) and an optional compass
  // reading; resamples when the weights call for it. Throws std::invalid_argument when
  // ranges.size() != NL, std::logic_error before any initialisation.
  void update(const std::vector<double>& ranges, std::optional<double> compass = std::nullopt);
  // The same, where another detector (a leg tracker, a camera) tells which returns stand
  // in front of the map: foreground[j] 1 where a person stopped beam j. It replaces
  // foreground.h's guess wherever the options read one (the searches and their cloud's
  // weighing, the verdict's residual, SensorModelOptions::short_only_foreground). Throws
  // std::invalid_argument when foreground.size() != NL.
  void update(const std::vector<double>& ranges, std::optional<double> compass, const std::vector<uint8_t>& foreground);
  // The latest scan's returns taken as foreground (given, or guessed when an option reads
  // them; empty when none was needed).
  const std::vector<uint8_t>& last_foreground() const { return last_foreground_; }

  PoseEstimate estimate() const;
  // Whether the cloud holds two or more places that explain the scans alike (ambiguity.h,
  // options().ambiguity's rule; the Likelihood rule scores the last ambiguity.scans scans,
  // placed as the global search stitches them (odometry, its turns corrected by the
  // compass and in place by the scans), and falls back to the Weight rule before any
  // scan): then
  // estimate().pose is one of look-alike places, not a pose to report.
  Ambiguity ambiguity() const { return ambiguity(options_.ambiguity.rule); }
  Ambiguity ambiguity(AmbiguityRule rule) const;

  const std::vector<Pose>& poses() const { return poses_; }
  const std::vector<double>& weights() const { return weights_; }  // normalized
  const std::vector<double>& beam_angles() const { return beams_; }
  const ParticleFilterOptions& options() const { return options_; }
  const RayCaster& ray_caster() const { return *caster_; }
  size_t updates() const { return updates_; }
  size_t resamplings() const { return resamplings_; }
  // Sum of the phi applied by the last update's stages: 1 when the scan counted in full.
  double last_tempering() const { return last_phi_; }
  // The candidates of the last global search, best first by cast rays (all M of them,
  // score: the log-likelihood of the stitched scans), and whether updates still search.
  const std::vector<Candidate>& last_candidates() const { return candidates_; }
  bool searching() const { return global_phase_; }
  // A deferred look around (defer_look_around) keeps its scans for one search at its end:
  // until then the cloud is the initial one, no estimate.
  bool awaiting_search() const { return global_phase_ && options_.defer_look_around; }
  // The refined places of the last settle (ParticleFilterOptions::settle_after), best
  // first (score: the log-likelihood of every recent scan), before the margin; empty
  // before one.
  const std::vector<Candidate>& last_settle() const { return settled_; }
  // The last search's places kept for the ambiguity verdict (AmbiguityOptions::rivals), where
  // the odometry since has carried them; empty before a search.
  const std::vector<Pose>& rivals() const { return rivals_; }
  // The log-likelihood of the recent scans (the last ambiguity.scans, each at its pose
  // from the latest stitched as for the global search) seen from `place`, the latest
  // scan's pose: what settling ranks places by, and (per beam) the Likelihood rule.
  double recent_log_likelihood(const Pose& place) const;
  // The same per beam, as a score that stitches the recent scans once for every place it
  // is asked about: the Likelihood rule's score, and the trials' (localization_trials.h)
  // for telling a wrong place the scans favour from a truth the filter lost. Valid while
  // the filter is not updated; not thread-safe (one buffer of cast rays).
  PlaceScore recent_fit() const;
  // The negated residual of the recent scans seen from `place` (AmbiguityOptions::rivals):
  // the mean over their beams of min(((measured - cast) / rival_sigma)^2, rival_max_z2).
  // Valid as recent_fit(), and callable from several threads at once.
  PlaceScore recent_residual() const;
  // The same with each recent scan registered at a place (AmbiguityOptions::register_scans):
  // at its best pose within the window around where the stitching puts it. The score it
  // returns keeps those poses relative to the latest scan's (RegisteredScans). Valid and
  // callable as recent_residual().
  RegisteredResidual registered_residual() const;

 private:
  // The largest phi <= most that keeps tempering_ess of the particles effective.
  double choose_tempering(const std::vector<double>& log_likelihood, double most) const;
  double effective_sample_size() const;  // of the normalized weights
  void normalize_weights();
  void resample();
  void roughen(double factor = 1);
  // The global phase's cloud from a search on the scans so far; false (cloud kept) when
  // they hit nothing.
  bool reseed_from_search(double compass);
  // The global search, built on the map at its first use.
  const GlobalSearch& global_search();
  // Each recent scan's pose relative to the latest, and the score above with them.
  std::vector<Odometry> recent_offsets() const;
  // The recent scans and their kept beams, for recent_residual() and registered_residual().
  struct ResidualScans;
  std::shared_ptr<const ResidualScans> residual_scans() const;
  static PlaceScore stitched_residual(std::shared_ptr<const ResidualScans> scans);
  RegisteredResidual registered_residual(std::shared_ptr<const ResidualScans> scans) const;
  double recent_log_likelihood(const Pose& place, const std::vector<Odometry>& offsets,
                               std::vector<double>& synthetic) const;
  // Settling (ParticleFilterOptions::settle_after): the cloud from every recent scan at once.
  void settle(double compass);
  // The motion between two scans of the global phase for stitching them: odometry, its
  // turn corrected by the compass readings and, turning in place, by the scans.
  struct Scan;
  Odometry stitching_step(const Scan& before, const Scan& after) const;
  // Whether a step's odometry is a turn in place (turn_in_place, turn_in_place_sds).
  bool turned_in_place(const Odometry& u) const;
  // Scans (history_ or recent_) stitched into the latest one's frame, at most max_points.
  StitchedScan stitch(const std::vector<Scan>& scans, size_t max_points) const;
  // Weights from log-likelihoods (tempered), resampling and roughening when due; returns
  // the phi applied, at most `most`.
  double weigh(double most, double roughening = 1);

  ParticleFilterOptions options_;
  std::vector<double> beams_;
  SensorModel sensor_;
  SensorModel global_sensor_;  // sensor_ with global_short_beyond: the global phase's
  SensorModel search_sensor_;  // the rerank's and the searched cloud's (search_short_only_foreground)
  // The model that weighs the cloud and the verdict's places: the global phase's until
  // the next init_pose.
  const SensorModel& weighing_sensor() const { return from_global_ ? global_sensor_ : sensor_; }
  MotionModel motion_;
  CompassPrior compass_;
  std::shared_ptr<const RayCaster> caster_;
  Map map_;  // for the global search, built when first needed
  std::unique_ptr<FreeSpace> free_space_;
  std::shared_ptr<const GlobalSearch> search_;
  struct Scan {
    Odometry since_previous;  // odometry from the previous scan to this one
    std::vector<double> ranges;
    std::optional<double> compass;  // the reading taken with the scan
    std::vector<uint8_t> foreground;  // per beam (foreground.h); empty: not looked for
    const uint8_t* in_front() const { return foreground.empty() ? nullptr : foreground.data(); }
  };
  // A scan's foreground, when an option will read it (else empty).
  std::vector<uint8_t> foreground_of(const std::vector<double>& ranges) const;
  // update()'s body, with the scan's foreground decided.
  void correct(const std::vector<double>& ranges, std::optional<double> compass, std::vector<uint8_t> front);
  std::vector<uint8_t> last_foreground_;
  bool global_phase_ = false;
  std::optional<double> init_compass_;  // the reading of init_global
  Odometry since_scan_;                 // odometry since the last scan, in the global phase
  std::vector<Scan> history_;           // the global phase's scans, oldest first
  // After a search, the update weighs the new cloud on every scan of history_ at these
  // poses relative to the latest (the stitched scan's), not on the latest scan alone.
  std::vector<Pose> searched_at_;
  size_t searches_ = 0;
  size_t searched_scans_ = 0;  // history_'s scans at the last search
  bool looking_around_ = false;  // only turns in place since init_global
  bool from_global_ = false;     // init_global was the last initialisation
  size_t since_global_ = 0;      // updates since init_global
  std::vector<Candidate> candidates_;
  std::vector<Candidate> settled_;
  // The last search's best distinct places (AmbiguityOptions::rivals), best first,
  // carried by the odometry since: the ambiguity verdict scores them beside the cloud's.
  std::vector<Pose> rivals_;
  void keep_rivals(const std::vector<Candidate>& ranked, double beams);
  // AmbiguityOptions::drop_ruled_out_rivals, once the window of recent scans is full.
  void drop_ruled_out_rivals();
  // The last ambiguity.scans scans (their odometry from the scan before and compass
  // reading, as history_'s), for the ambiguity verdict; cleared by init_global and
  // init_pose, kept by set_particles and set_map.
  std::vector<Scan> recent_;
  Odometry since_recent_;  // odometry since recent_'s last scan
  std::vector<Pose> poses_;
  std::vector<double> weights_;  // normalized, sum 1
  std::vector<double> log_likelihood_;  // of the last scan, per particle
  std::mt19937_64 rng_;                 // sequential steps
  std::vector<std::mt19937_64> chunk_rngs_;  // one per thread chunk
  size_t updates_ = 0, resamplings_ = 0;
  double last_phi_ = 1;
};

}  // namespace fleetmap::localization
