#pragma once
// The localization trials (SPEC 6: global localization and tracking on the real maps),
// shared by bench-localization and `fleetmap-robot --trials` (one runner, one report):
//
//  1. global localization: from a compass-only prior, the share of trials whose estimate
//     is within 0.3 m and 3 degrees after at most `updates` updates and stays so to the
//     last (the robot looking around, then wandering global_step metres between scans); start poses in free
//     space with at least min_hit_fraction of the beams hitting a wall;
//  2. tracking: RMS and maximum error along a `drive`-metre wander (a scan every 0.25 m,
//     odometry noise), beside dead reckoning from the same odometry (the baseline);
//  3. kidnapping (client/localization/lost_detector.h): a tracked robot moved to a random
//     place without odometry; the updates until the detector says lost, then until a
//     new global localization (a look around, as at boot) is within 0.3 m and 3 degrees;
//     and the false alarms of the detector over `false_alarm_drive` metres of normal
//     driving.
//
// Everything is seeded (TrialSettings::seed): the same settings give the same trials.
#include <cstdint>
#include <cstdio>
#include <memory>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "client/sim/laser_simulator.h"
#include "client/sim/twin_places.h"
#include "client/localization/lost_detector.h"
#include "client/localization/particle_filter.h"
#include "common/map/map.h"
#include "common/raycast/ray_caster.h"

namespace fleetmap::localization {

// The twin checks of one map's trials (TrialSettings::twins): they depend on the start
// and the path, which every preset's trials share, not on the filter; so a caller that
// runs several presets on one map with the same settings checks each start once.
struct TwinCache {
  std::shared_ptr<const GlobalSearch> search;  // the oracle's own, built at first use
  std::map<int, TwinCheck> by_trial;  // sparse: --first-trial may start anywhere
};

struct TrialSettings {
  ParticleFilterOptions filter;  // the configuration under test
  LaserSimulatorOptions laser;
  int trials = 100;
  int first_trial = 0;  // index of the first (each trial's draws depend on its index alone)
  int updates = 10;
  double global_step = 0.5;  // metres between scans during global localization
  // Global localization starts with a look around, as SimRobot's does: the first
  // look_around steps turn in place by look_around_turn (0: wander from the start).
  int look_around = 6;
  double look_around_turn = deg2rad(60.0);
  double drive = 200;        // metres of the tracking drive
  double min_hit_fraction = 0.5;
  // Every drive keeps where at least this share of 36 rays around meets a wall within the
  // laser's range (DriveOptions::min_walls_around; the starts' min_hit_fraction). 0: the
  // robot may wander off the map into ground no scan sees, as before 2026-12-06.
  double drive_min_walls = 0.5;
  double compass_sd = deg2rad(1.0);  // the compass's own error (clamped to +-3 degrees)
  uint64_t seed = 1;
  std::FILE* per_trial = nullptr;  // a line per global trial (start, outcome) when set
  // Kidnapping trials: this many, each after kidnap_after metres of tracking; updates
  // come every scan_period_s (SimRobot's rate while driving) for the times reported.
  int kidnaps = 0;
  double kidnap_after = 20;
  double false_alarm_drive = 0;  // metres of driving without a kidnap (0: none)
  double scan_period_s = 0.2;
  int recover_updates = 30;      // a recovery not within bounds by then failed; 0: no recovery
  int report_after = 3;          // a recovery reports its pose once it holds this many scans (report_gate.h)
  // The filter is told which returns the simulated people stopped (ParticleFilter::update's
  // foreground) instead of guessing them (foreground.h): the ceiling of any people detector.
  bool exact_people = false;
  LostDetectorOptions lost;
  // The sensor model's short_beyond for every preset, in every phase (sensor_model.h);
  // negative: the preset's.
  double short_beyond = -1;
  // ParticleFilterOptions::global_short_beyond for every preset; negative: the preset's.
  double global_short_beyond = -1;
  // SensorModelOptions::short_only_foreground for every preset: 1 on, 0 off, negative: the preset's.
  int short_only_foreground = -1;
  // ParticleFilterOptions::search_short_only_foreground for every preset but seed: 1 on, 0 off, negative: the preset's.
  int search_short_only_foreground = -1;
  // Overrides of ParticleFilterOptions for every preset but `seed` (the baseline):
  // search_updates, tempering_ess, tempering_stages and settle_after (negative: the preset's),
  // search_candidates, search_clusters and search_particles (0: the preset's).
  int search_updates = -1;
  size_t search_candidates = 0, search_clusters = 0, search_particles = 0;
  double tempering_ess = -1;
  int tempering_stages = -1;
  int settle_after = -1;  // ParticleFilterOptions::settle_after (negative: the preset's)
  // The likelihood field's sigma and per-point floor (GlobalSearchOptions; negative: the preset's).
  double search_sigma = -1, search_max_penalty = -1;
  // ParticleFilterOptions::search_drops_foreground: 1 on, 0 off, negative: the preset's;
  // foreground_width > 0 sets ForegroundOptions::max_width.
  int search_drops_foreground = -1;
  double foreground_width = -1;
  // AmbiguityOptions::rivals: 1 on, 0 off, negative: the preset's.
  int rivals = -1;
  // AmbiguityOptions::drop_ruled_out_rivals: 1 on, 0 off, negative: the preset's.
  int drop_ruled_out_rivals = -1;
  double rival_drop_margin_z2 = -1;  // AmbiguityOptions::rival_drop_margin_z2; negative: the preset's
  // AmbiguityOptions::register_scans: 1 on, 0 off, negative: the preset's.
  int register_scans = -1;
  // AmbiguityOptions::register_moves_place: 1 on, 0 off, negative: the preset's.
  int register_moves_place = -1;
  // AmbiguityOptions::rival_margin_z2 (negative: the preset's).
  double rival_margin_z2 = -1;
  // AmbiguityOptions::candidates_by_residual: 1 on, 0 off, negative: the preset's.
  int candidates_by_residual = -1;
  // ParticleFilterOptions::turn_in_place_sds (0: turn_in_place alone; negative: the preset's).
  double turn_in_place_sds = -1;
  // ParticleFilterOptions::roughening_max_xy (metres; negative: the preset's).
  double roughening_max_xy = -1;
  // ParticleFilterOptions::roughening_stage_decay (negative: the preset's).
  double roughening_stage_decay = -1;
  // KldOptions: min_particles (0: the preset's), bin_xy in metres and bin_theta in degrees
  // (negative: the preset's).
  size_t kld_min_particles = 0;
  // ParticleFilterOptions::tracking_min_particles, KLD's floor from a known pose on (0: the
  // preset's).
  size_t tracking_min_particles = 0;
  // ParticleFilterOptions::tracking_sigma_m (metres; not positive: the preset's).
  double tracking_sigma_m = -1;
  double kld_bin_xy = -1;
  double kld_bin_theta_deg = -1;
  // Tracking also drives a fixed cloud of NP particles beside the KLD one (report_preset).
  bool tracking_fixed = true;
  // After each global trial whose estimate ends out of bounds: whom the scans favour, the
  // truth or the estimate (GlobalTrial::truth_fit), to tell the model's failures (no
  // filter on it could pick the truth) from the filter's (it lost a better place).
  bool explain = false;
  // Whether each start has a twin (twin_places.h): a place no scan tells from it, where
  // the right answer is "ambiguous". Each trial's outcome is then scored by its kind of start.
  bool twins = false;
  // Shared by the presets run on one map (the caller makes one per map); none: each call
  // to run_global_trials checks its starts itself.
  std::shared_ptr<TwinCache> twin_cache;
};

// A global trial's outcome: within bounds and staying so to the last update, with one
// place in the cloud (success); two places or more of comparable weight at the last
// update (ambiguous, ambiguity.h: the filter says it cannot tell, whatever its heaviest
// cluster); otherwise wrong (a pose off by more than the bounds, reported as if right).
enum class TrialOutcome { Success, Ambiguous, Wrong };
const char* to_string(TrialOutcome o);

struct GlobalTrial {
  int trial = 0;
  Pose start;
  TrialOutcome outcome = TrialOutcome::Wrong;
  int updates = 0;         // updates made
  int within_from = -1;    // update from which the estimate stayed within bounds; -1: not within at the end
  size_t places = 0;       // places of the ambiguity verdict at the last update
  // The Weight rule's verdict on the same cloud (ambiguity.h), for comparison, and the
  // Likelihood rule's gaps per beam (NaN: fewer than two candidates scored).
  TrialOutcome outcome_weight_rule = TrialOutcome::Wrong;
  size_t places_weight_rule = 0;
  double runner_up_gap = 0, heaviest_gap = 0;
  double final_error = 0;  // metres
  double seconds = 0;      // computation of this localization
  // TrialSettings::explain, for an estimate out of bounds at the end (NaN otherwise): the
  // log-likelihood per beam of the recent scans (ParticleFilter::recent_fit) at the truth
  // and at the estimate, each refined to its best pose nearby (place_refinement.h).
  double truth_fit = NAN, estimate_fit = NAN;
  // TrialSettings::explain, every trial: the rank, in the last global search's candidates
  // reranked on cast rays (ParticleFilter::last_candidates), of the first within 0.5 m
  // and 5 degrees of the truth at that search; -1: none was; -2: no search.
  int search_rank = -2;
  // TrialSettings::twins: 1 when the start has a twin (twin_places.h), 0 when not, -1
  // unchecked; the other place that fits best and its mean term per beam.
  int twin = -1;
  Pose twin_place;
  double twin_mean_z2 = NAN;
  // The twin is one of the verdict's places, which the oracle's own search missed.
  bool twin_named_by_verdict = false;
  // With people (TrialSettings::twins): the same check on what the people left to see
  // (twin_places.h, PeopleInPath): 1 twin, 0 not, -1 unchecked.
  int twin_in_crowd = -1;
  double twin_in_crowd_mean_z2 = NAN;
};

// Whom the scans favour in an explained trial: the estimate by more than `tie` per beam
// (a wrong place explains them better: the model's failure), the truth by more (the
// filter's), or neither.
enum class Favoured { Estimate, Tie, Truth, Unexplained };
Favoured favoured(const GlobalTrial& t, double tie);
const char* to_string(Favoured f);

// Whether a checked start has a near twin: no twin, and another place scoring at most
// `line` (TwinOptions::near_twin_mean_z2).
bool near_twin(const GlobalTrial& t, double line);

// The starts with a near twin and their outcomes.
struct NearTwins {
  int starts = 0, success = 0, ambiguous = 0, wrong = 0;
};

struct GlobalResult {
  // converged: within bounds at the end, whether or not ambiguous (the figure before the
  // ambiguity verdict); success + ambiguous + wrong = trials.
  int trials = 0, converged = 0, success = 0, ambiguous = 0, wrong = 0;
  int success_weight_rule = 0, ambiguous_weight_rule = 0, wrong_weight_rule = 0;  // ambiguity.h's Weight rule
  // TrialSettings::explain: the trials out of bounds at the end, by whom the scans favour
  // (favoured(), tie kFitTie).
  int favour_estimate = 0, favour_tie = 0, favour_truth = 0;
  // Of the trials out of bounds, by where the last search put the truth: among the first
  // search_clusters candidates (it got particles), ranked lower, or not found at all.
  int truth_in_clusters = 0, truth_ranked_out = 0, truth_not_found = 0;
  size_t beams_hidden = 0, beams_seen = 0;  // explain, with people: beams a person stopped, of all
  // TrialSettings::twins: the starts with a twin and their outcomes. The right answer is
  // success on a start without one and ambiguous on one with one (right()).
  bool twins_checked = false;
  int twin_starts = 0, twin_success = 0, twin_ambiguous = 0, twin_wrong = 0;
  int twins_named_by_verdict = 0;  // GlobalTrial::twin_named_by_verdict (each one ambiguous)
  int right() const { return success - twin_success + twin_ambiguous; }
  // Starts with a near twin (near_twin()), counted from per_trial. There the verdict,
  // whose margin is the oracle's line, says the pose or "ambiguous" as the noise falls:
  // right_near_either() counts either as right, a wrong pose still wrong
  // (docs/localization.md, "The campus's misses are near twins").
  NearTwins near_twins(double line = TwinOptions{}.near_twin_mean_z2) const;
  int right_near_either() const { return right() + near_twins().ambiguous; }
  // The same, twins judged on what the people left to see (GlobalTrial::twin_in_crowd).
  bool twins_in_crowd_checked = false;
  int crowd_twin_starts = 0, crowd_twin_success = 0, crowd_twin_ambiguous = 0;
  int right_in_crowd() const { return success - crowd_twin_success + crowd_twin_ambiguous; }
  std::vector<GlobalTrial> per_trial;
  std::vector<int> first_within;    // update at which the estimate first got within bounds
  std::vector<double> final_error;  // metres, per trial
  double seconds = 0;               // all trials, without setup
  std::vector<double> trial_seconds;  // per trial
  double setup_seconds = 0;         // once per map: the global search's likelihood field
};

struct TrackResult {
  double rms = 0, max = 0, rms_theta = 0, dead_reckoning_rms = 0, dead_reckoning_final = 0;
  double driven = 0, mean_particles = 0, seconds = 0;
  int updates = 0;
};

struct KidnapResult {
  int trials = 0, detected = 0, recovered = 0, wrong = 0;  // wrong: reported a pose out of bounds
  std::vector<double> wrong_error_m;                        // how far, each
  // Not detected within 10 s, but the tracking filter found the robot again by itself
  // (its estimate within 0.3 m and 3 degrees at the end): no harm done.
  int found_by_itself = 0;
  std::vector<int> detect_updates;   // per detected kidnap: updates from the kidnap to "lost"
  std::vector<int> recover_updates;  // per recovery: updates from "lost" to within bounds
  double recover_compute_s = 0;      // computation of the recoveries, all of them
  int false_alarms = 0;              // "lost" before a kidnap, or during the drive without one
  // Of those, the ones where the tracking filter had lost the robot by itself (its
  // estimate more than 1 m off when the detector spoke): a true alarm of another cause,
  // counted apart so that neither hides the other.
  int alarms_while_off = 0;
  int alarms_of_right_pose = 0;  // of those, said of an estimate within 0.3 m and 3 degrees
  int slips_unsaid = 0;          // the estimate more than 1 m off for 3 s, and no "lost" said
  std::vector<double> alarm_error_m, alarm_error_deg;  // the estimate's error at each false alarm
  double driven_without_kidnap = 0;  // metres of driving in which a "lost" is a false alarm
  int scans_without_kidnap = 0, blind_scans = 0;  // of that driving; blind: under a tenth of the beams returned
  // Of those scans, with people: how many stood in view, and the beams they stopped (0.3 m
  // or more short of the wall behind), of all. How crowded "30 people" is on this map.
  size_t people_in_view = 0, beams_hidden = 0, beams_seen = 0;
};

// Per beam: closer fits than this are a tie (settling's measurement, docs/localization.md).
inline constexpr double kFitTie = 0.002;

GlobalResult run_global_trials(const Map& map, std::shared_ptr<const RayCaster> world, const TrialSettings& s);
TrackResult run_tracking_trial(const Map& map, std::shared_ptr<const RayCaster> world, const TrialSettings& s,
                               bool adaptive);

KidnapResult run_kidnap_trials(const Map& map, std::shared_ptr<const RayCaster> world, const TrialSettings& s);
void report_kidnap(std::FILE* out, const Map& map, std::shared_ptr<const RayCaster> world, const TrialSettings& s);

// The presets by name: "seed" (ParticleFilterOptions::seed_model), "robust", "search"
// (robust_search, the robot's default), "fast" (fast_search); nullopt for another name.
std::optional<ParticleFilterOptions> preset(const std::string& name);
const std::vector<std::string>& preset_names();
// The filter every trial of preset `name` runs (base.filter for another name): base's NP,
// threads and short_beyond, and for every preset but `seed` base's other overrides.
ParticleFilterOptions trial_filter(const TrialSettings& base, const std::string& name);

// An AMRL map (*.vectormap.txt), a generated one ("gen:KIND[:SEED]", generated_maps.h)
// or a seed-format one.
Map load_map_file(const std::string& path);

// The report: a header per map, then per preset its global and tracking lines (the
// settings' filter replaced by the preset, keeping NP and threads).
void report_map_header(std::FILE* out, const std::string& path, const Map& map, const TrialSettings& s);
// Returns the global trials' result when they ran.
std::optional<GlobalResult> report_preset(std::FILE* out, const Map& map, std::shared_ptr<const RayCaster> world,
                                          const TrialSettings& s, const std::string& name, bool global, bool tracking);

// The per-map table: a row per map and config (trials, success, ambiguous, wrong, the
// figure before the verdict, time p50/p95 per localization), Markdown.
struct TableRow {
  std::string map, config;
  GlobalResult result;
};
void print_table(std::FILE* out, const std::vector<TableRow>& rows);
// The per-trial CSV: a header, then a row per trial of every row.
void write_trials_csv(std::FILE* out, const std::vector<TableRow>& rows, uint64_t seed);

}  // namespace fleetmap::localization
