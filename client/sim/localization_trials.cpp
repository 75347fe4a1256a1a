#include "client/sim/localization_trials.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <random>
#include <string>

#include "client/localization/report_gate.h"
#include "client/sim/drive_simulator.h"
#include "client/sim/generated_maps.h"
#include "client/sim/twin_places.h"
#include "client/localization/free_space.h"
#include "client/localization/global_search.h"
#include "client/localization/place_refinement.h"
#include "common/io/read_map_file.h"

namespace fleetmap::localization {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

double compass_reading(const Pose& truth, double sd, double half_width, std::mt19937_64& rng) {
  std::normal_distribution<double> n(0.0, sd);
  return normalize_angle(truth.theta + std::clamp(n(rng), -half_width, half_width));
}

double percentile(std::vector<int> v, double q) {
  if (v.empty()) return NAN;
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, static_cast<size_t>(q * v.size()))];
}

const char* describe(const ParticleFilterOptions& f) {
  return f.sensor.combination == BeamCombination::Harmonic ? "eq. (6) harmonic" : "beam product";
}

std::shared_ptr<const GlobalSearch> make_search(const Map& map, const ParticleFilterOptions& f) {
  if (!f.global_search) return nullptr;
  GlobalSearchOptions so = f.search;
  so.field.margin = f.laser.rmax;
  so.field.laser_height = f.laser.laser_height;
  so.threads = f.threads;
  return std::make_shared<GlobalSearch>(map, so);
}

// The beams a simulated person stopped: 0.3 m or more short of the wall (the noise is
// 0.05 m). Handed to the filter under TrialSettings::exact_people; explain counts them.
std::vector<uint8_t> people_returns(const LaserSimulator& laser, const Pose& truth, const std::vector<double>& ranges) {
  const std::vector<double> bare = laser.true_scan(truth);
  std::vector<uint8_t> stopped(ranges.size());
  for (size_t j = 0; j < ranges.size(); ++j) stopped[j] = ranges[j] < bare[j] - 0.3;
  return stopped;
}

// The filter's update, told which returns are people when `people` holds them (empty: it
// guesses them itself).
void update_filter(ParticleFilter& pf, const std::vector<double>& ranges, double compass,
                   const std::vector<uint8_t>& people) {
  if (people.empty())
    pf.update(ranges, compass);
  else
    pf.update(ranges, compass, people);
}

// The people's returns when the filter is to be told them (TrialSettings::exact_people), else empty.
std::vector<uint8_t> told_people(const LaserSimulator& laser, const TrialSettings& s, const Pose& truth,
                                 const std::vector<double>& ranges) {
  return s.exact_people && s.laser.people > 0 ? people_returns(laser, truth, ranges) : std::vector<uint8_t>{};
}

// One global localization as at boot (SimRobot::localize): a filter initialised from the
// compass alone, a look around then a wander from `start`, up to max_updates updates.
// The caller draws the laser's and the driver's seeds (each caller in its own order, so
// that its figures stay those of its seeds).
struct GlobalRunSeeds {
  uint64_t laser = 0, drive = 0;
};

struct GlobalRun {
  int updates = 0;       // updates made
  int first_within = -1;  // update from which the estimate stayed within bounds; -1: not within at the end
  int converged_at = -1;  // first update whose estimate converged (PoseEstimate::converged); -1: none
  bool within = false;   // the last update's estimate within 0.3 m and 3 degrees
  double error = 0;      // metres, the last update's
  size_t places = 0;     // of the last update's ambiguity verdict (the options' rule)
  size_t places_weight_rule = 0;  // of the Weight rule's, on the same cloud
  double runner_up_gap = NAN, heaviest_gap = NAN;  // the Likelihood rule's (ambiguity.h)
  double truth_fit = NAN, estimate_fit = NAN;      // TrialSettings::explain (GlobalTrial)
  int search_rank = -2;                            // likewise
  size_t beams_hidden = 0, beams_seen = 0;         // likewise: beams a person stopped, of all
  std::vector<Pose> path;                          // the truth at each update (twin_places.h)
  PeopleInPath people;                             // with people and twins: what they stopped
  std::vector<Pose> verdict_places;                // the last verdict's places (at the last scan)
  double explain_seconds = 0;                      // spent on explain's fits: not localization
};

DriveOptions trial_drive(const TrialSettings& s) {
  DriveOptions drive;
  drive.min_walls_around = s.drive_min_walls;
  return drive;
}

bool within_bounds(const Pose& e, const Pose& truth) {
  return distance(e, truth) < 0.3 && std::fabs(angle_diff(e.theta, truth.theta)) < deg2rad(3.0);
}

// stop_when_converged: end at the first pose the robot would report (converged, and no
// look-alike place: a recovery trusts it then); otherwise run all max_updates (a trial
// asks that the estimate stays within).
GlobalRun run_global_localization(const Map& map, std::shared_ptr<const RayCaster> world,
                                  std::shared_ptr<const GlobalSearch> search, const ParticleFilterOptions& fo,
                                  const TrialSettings& s, const Pose& start, GlobalRunSeeds seeds,
                                  std::mt19937_64& rng, int max_updates, bool stop_when_converged) {
  ParticleFilter pf(map, world, fo);
  if (search) pf.set_global_search(std::move(search));
  LaserSimulator laser(world, s.laser, seeds.laser);
  DriveOptions drive = trial_drive(s);
  drive.step = s.global_step;
  drive.look_around_steps = s.look_around;
  drive.look_around_turn = s.look_around_turn;
  WanderDriver driver(world, start, drive, seeds.drive);
  Pose truth = start;
  pf.init_global(compass_reading(truth, s.compass_sd, fo.compass_half_width, rng));
  GlobalRun run;
  ReportGate gate(s.report_after);
  const Candidate* searched = nullptr;  // the last search's candidates seen (explain)
  for (int u = 1; u <= max_updates; ++u) {
    if (u > 1) {
      const DriveStep st = driver.step();
      truth = st.truth;
      pf.predict(st.odometry);
    }
    run.path.push_back(truth);
    const std::vector<double> ranges = laser.scan(truth);
    // Cast once for both uses: the noiseless scan is a ray per beam.
    const bool crowd = (s.explain || s.twins) && s.laser.people > 0;
    const std::vector<uint8_t> stopped = crowd ? people_returns(laser, truth, ranges) : told_people(laser, s, truth, ranges);
    if (s.twins && s.laser.people > 0) {
      run.people.stopped.push_back(stopped);
      run.people.ranges.push_back(ranges);
    }
    if (s.explain && s.laser.people > 0) {
      run.beams_hidden += std::count(stopped.begin(), stopped.end(), 1);
      run.beams_seen += ranges.size();
    }
    update_filter(pf, ranges, compass_reading(truth, s.compass_sd, fo.compass_half_width, rng),
                  s.exact_people ? stopped : std::vector<uint8_t>{});
    if (s.explain && !pf.last_candidates().empty() && pf.last_candidates().data() != searched) {
      // A new search this update: its candidates are poses of the scan just taken.
      searched = pf.last_candidates().data();
      const std::vector<Candidate>& c = pf.last_candidates();
      const auto near = std::find_if(c.begin(), c.end(), [&](const Candidate& k) {
        return distance(k.pose, truth) < 0.5 && std::fabs(angle_diff(k.pose.theta, truth.theta)) < deg2rad(5.0);
      });
      run.search_rank = near == c.end() ? -1 : static_cast<int>(near - c.begin());
    }
    const PoseEstimate e = pf.estimate();
    run.updates = u;
    run.error = distance(e.pose, truth);
    run.within = within_bounds(e.pose, truth);
    if (run.within && run.first_within < 0) run.first_within = u;
    if (!run.within) run.first_within = -1;  // must stay within to the end
    if (stop_when_converged) {
      // As the robot does (SimRobot::localize): a pose is reported once the cloud has
      // converged and the verdict finds no look-alike place, on report_after scans in a
      // row (report_gate.h); until then it looks on.
      if (gate.update(e.converged && !pf.awaiting_search() && !pf.ambiguity().ambiguous())) {
        run.converged_at = u;
        break;
      }
    } else if (e.converged && run.converged_at < 0) {
      run.converged_at = u;
    }
  }
  const Ambiguity a = pf.ambiguity();
  run.places = a.places.size();
  run.verdict_places = a.places;
  run.runner_up_gap = a.runner_up_gap;
  run.heaviest_gap = a.heaviest_gap;
  run.places_weight_rule = pf.ambiguity(AmbiguityRule::Weight).places.size();
  if (s.explain && !run.within) {
    const auto explain_t0 = Clock::now();
    const PlaceScore fit = pf.recent_fit();
    run.truth_fit = refine_place(truth, fit).score;
    run.estimate_fit = refine_place(pf.estimate().pose, fit).score;
    run.explain_seconds = seconds_since(explain_t0);
  }
  return run;
}

}  // namespace

GlobalResult run_global_trials(const Map& map, std::shared_ptr<const RayCaster> world, const TrialSettings& s) {
  GlobalResult res;
  const FreeSpace free_space(map);
  const std::vector<double> beams = evenly_spread_angles(s.laser.beams, s.laser.fov);
  // One search (its likelihood field) for every trial on this map, as one robot keeps it.
  const auto setup = Clock::now();
  const std::shared_ptr<const GlobalSearch> search = make_search(map, s.filter);
  if (search) res.setup_seconds = seconds_since(setup);
  // The twins' own search (the default field), whatever the preset under test uses.
  std::shared_ptr<TwinCache> twins = s.twin_cache;
  if (s.twins && !twins) twins = std::make_shared<TwinCache>();
  if (twins && !twins->search) {
    GlobalSearchOptions so;
    so.field.margin = world->options().rmax;
    so.field.laser_height = world->options().laser_height;
    so.threads = s.filter.threads;
    twins->search = std::make_shared<const GlobalSearch>(map, so);
  }
  res.twins_checked = s.twins;
  double twin_seconds = 0, explain_seconds = 0;  // left out of the localizations' time
  const auto t0 = Clock::now();
  for (int t = s.first_trial; t < s.first_trial + s.trials; ++t) {
    const auto trial_t0 = Clock::now();
    std::mt19937_64 rng(s.seed * 1000003 + t);
    const Pose start = pick_start_pose(free_space, *world, beams, s.min_hit_fraction, 0.5, rng);
    ParticleFilterOptions fo = s.filter;
    fo.seed = s.seed * 7919 + t;
    GlobalRunSeeds seeds;
    seeds.laser = rng();
    seeds.drive = rng();
    const GlobalRun run = run_global_localization(map, world, search, fo, s, start, seeds, rng, s.updates, false);
    GlobalTrial g;
    g.trial = t;
    g.start = start;
    g.updates = run.updates;
    g.within_from = run.first_within;
    g.places = run.places;
    g.places_weight_rule = run.places_weight_rule;
    g.runner_up_gap = run.runner_up_gap;
    g.heaviest_gap = run.heaviest_gap;
    g.final_error = run.error;
    g.truth_fit = run.truth_fit;
    g.estimate_fit = run.estimate_fit;
    g.search_rank = run.search_rank;
    res.beams_hidden += run.beams_hidden;
    res.beams_seen += run.beams_seen;
    g.seconds = seconds_since(trial_t0) - run.explain_seconds;
    explain_seconds += run.explain_seconds;
    res.trial_seconds.push_back(g.seconds);
    const auto outcome = [&](size_t places) {
      return places >= 2 ? TrialOutcome::Ambiguous : run.first_within > 0 ? TrialOutcome::Success : TrialOutcome::Wrong;
    };
    g.outcome = outcome(run.places);
    g.outcome_weight_rule = outcome(run.places_weight_rule);
    ++res.trials;
    if (run.first_within > 0) {
      ++res.converged;
      res.first_within.push_back(run.first_within);
    }
    res.success += g.outcome == TrialOutcome::Success;
    res.ambiguous += g.outcome == TrialOutcome::Ambiguous;
    res.wrong += g.outcome == TrialOutcome::Wrong;
    res.success_weight_rule += g.outcome_weight_rule == TrialOutcome::Success;
    res.ambiguous_weight_rule += g.outcome_weight_rule == TrialOutcome::Ambiguous;
    res.wrong_weight_rule += g.outcome_weight_rule == TrialOutcome::Wrong;
    if (s.twins) {
      const auto twin_t0 = Clock::now();
      auto cached = twins->by_trial.find(t);
      if (cached == twins->by_trial.end())
        cached = twins->by_trial.emplace(t, find_twin(*world, *twins->search, run.path, beams, fo.compass_half_width)).first;
      TwinCheck tc = cached->second;
      // The verdict's places, carried back to the start: a twin the oracle's search missed
      // is a twin all the same (the same noiseless comparison; not cached, as it depends
      // on the filter under test).
      std::vector<Pose> also;
      if (run.verdict_places.size() >= 2 && !run.path.empty()) {
        const Odometry back = between(run.path.back(), run.path.front());
        for (const Pose& p : run.verdict_places) also.push_back(compose(p, back));
      }
      if (!tc.twin && !also.empty()) {
        TwinOptions only;
        only.candidates = 0;
        const TwinCheck named = find_twin(*world, *twins->search, run.path, beams, fo.compass_half_width, only, also);
        if (named.mean_z2 < tc.mean_z2) tc = named;
        g.twin_named_by_verdict = tc.twin;
      }
      if (s.laser.people > 0) {
        // Not cached: the people differ between the settings run on one map.
        const TwinCheck crowd =
            find_twin(*world, *twins->search, run.path, beams, fo.compass_half_width, {}, also, &run.people);
        g.twin_in_crowd = crowd.twin ? 1 : 0;
        g.twin_in_crowd_mean_z2 = crowd.mean_z2;
        res.twins_in_crowd_checked = true;
        if (crowd.twin) {
          ++res.crowd_twin_starts;
          res.crowd_twin_success += g.outcome == TrialOutcome::Success;
          res.crowd_twin_ambiguous += g.outcome == TrialOutcome::Ambiguous;
        }
      }
      g.twin = tc.twin ? 1 : 0;
      g.twin_place = tc.place;
      g.twin_mean_z2 = tc.mean_z2;
      if (tc.twin) {
        ++res.twin_starts;
        res.twin_success += g.outcome == TrialOutcome::Success;
        res.twin_ambiguous += g.outcome == TrialOutcome::Ambiguous;
        res.twin_wrong += g.outcome == TrialOutcome::Wrong;
        res.twins_named_by_verdict += g.twin_named_by_verdict;
      }
      twin_seconds += seconds_since(twin_t0);
    }
    res.final_error.push_back(run.error);
    switch (favoured(g, kFitTie)) {
      case Favoured::Estimate: ++res.favour_estimate; break;
      case Favoured::Tie: ++res.favour_tie; break;
      case Favoured::Truth: ++res.favour_truth; break;
      case Favoured::Unexplained: break;
    }
    if (s.explain && !run.within) {
      if (run.search_rank < 0) ++res.truth_not_found;
      else if (static_cast<size_t>(run.search_rank) < fo.search_clusters) ++res.truth_in_clusters;
      else ++res.truth_ranked_out;
    }
    res.per_trial.push_back(g);
    if (s.per_trial)
      std::fprintf(s.per_trial,
                   "  trial %d: start (%.2f, %.2f, %.1f deg): %s, %s, final error %.2f m, %zu place(s); weight rule %s, "
                   "%zu place(s); gaps per beam: runner-up %.3f, heaviest %.3f\n",
                   t, start.x, start.y, rad2deg(start.theta),
                   run.first_within > 0 ? ("within from update " + std::to_string(run.first_within)).c_str() : "not within",
                   to_string(g.outcome), run.error, run.places, to_string(g.outcome_weight_rule), run.places_weight_rule,
                   run.runner_up_gap, run.heaviest_gap);
    if (s.per_trial && !std::isnan(g.truth_fit))
      std::fprintf(s.per_trial, "    fit per beam: truth %.4f, estimate %.4f: the scans favour %s; truth at rank %d of the last search\n",
                   g.truth_fit, g.estimate_fit, to_string(favoured(g, kFitTie)), g.search_rank);
    if (s.per_trial && g.twin >= 0)
      std::fprintf(s.per_trial, "    %s: the other place that fits best, (%.2f, %.2f, %.1f deg), %.3f per beam\n",
                   g.twin_named_by_verdict ? "a twin (one of the verdict's places)" : g.twin ? "a twin" : "no twin", g.twin_place.x, g.twin_place.y, rad2deg(g.twin_place.theta),
                   g.twin_mean_z2);
    if (s.per_trial && g.twin_in_crowd >= 0)
      std::fprintf(s.per_trial, "    on what the people left to see: %s, %.3f per beam\n",
                   g.twin_in_crowd ? "a twin" : "no twin", g.twin_in_crowd_mean_z2);
  }
  res.seconds = seconds_since(t0) - twin_seconds - explain_seconds;
  return res;
}

TrackResult run_tracking_trial(const Map& map, std::shared_ptr<const RayCaster> world, const TrialSettings& s,
                               bool adaptive) {
  TrackResult res;
  std::mt19937_64 rng(s.seed * 31337);
  const FreeSpace free_space(map);
  const std::vector<double> beams = evenly_spread_angles(s.laser.beams, s.laser.fov);
  const Pose start = pick_start_pose(free_space, *world, beams, s.min_hit_fraction, 0.5, rng);
  ParticleFilterOptions fo = s.filter;
  fo.adaptive = adaptive;
  fo.kld.max_particles = fo.particles;
  ParticleFilter pf(map, world, fo);
  LaserSimulator laser(world, s.laser, rng());
  WanderDriver driver(world, start, trial_drive(s), rng());
  pf.init_pose(start, 0.1, deg2rad(2.0));
  Pose dead = start;
  double sq = 0, sq_theta = 0, sq_dead = 0, particles = 0;
  const auto t0 = Clock::now();
  while (res.driven < s.drive) {
    const DriveStep st = driver.step();
    res.driven += st.driven;
    dead = compose(dead, st.odometry);
    pf.predict(st.odometry);
    const std::vector<double> ranges = laser.scan(st.truth);
    update_filter(pf, ranges, compass_reading(st.truth, s.compass_sd, fo.compass_half_width, rng),
                  told_people(laser, s, st.truth, ranges));
    const PoseEstimate e = pf.estimate();
    const double err = distance(e.pose, st.truth), et = angle_diff(e.pose.theta, st.truth.theta);
    sq += err * err;
    sq_theta += et * et;
    sq_dead += distance(dead, st.truth) * distance(dead, st.truth);
    res.max = std::max(res.max, err);
    particles += static_cast<double>(e.particles);
    ++res.updates;
    res.dead_reckoning_final = distance(dead, st.truth);
  }
  res.seconds = seconds_since(t0);
  res.rms = std::sqrt(sq / res.updates);
  res.rms_theta = std::sqrt(sq_theta / res.updates);
  res.dead_reckoning_rms = std::sqrt(sq_dead / res.updates);
  res.mean_particles = particles / res.updates;
  return res;
}

namespace {

// A tracking filter (KLD sampling, as run_tracking_trial) with its lost detector, driven
// by one WanderDriver at a time; step() returns whether the detector says lost.
struct TrackedRobot {
  TrackedRobot(const Map& map, std::shared_ptr<const RayCaster> world, const TrialSettings& s, const Pose& start,
               uint64_t seed)
      : s_(s), world_(world), beams_(evenly_spread_angles(s.laser.beams, s.laser.fov)), rng_(seed),
        laser_(world, s.laser, rng_()), driver_(std::make_unique<WanderDriver>(world, start, trial_drive(s), rng_())),
        detector_(s.lost) {
    ParticleFilterOptions fo = s.filter;
    fo.adaptive = true;
    fo.kld.max_particles = fo.particles;
    fo.seed = seed * 7;
    filter_ = std::make_unique<ParticleFilter>(map, world, fo);
    filter_->init_pose(start, 0.1, deg2rad(2.0));
  }
  // One scan; the metres driven by the step.
  double step() {
    const DriveStep st = driver_->step();
    truth_ = st.truth;
    filter_->predict(st.odometry);
    const std::vector<double> scan = laser_.scan(st.truth);
    const auto hits = std::count_if(scan.begin(), scan.end(), [&](double r) { return r < laser_.rmax(); });
    blind_ = static_cast<double>(hits) < 0.1 * static_cast<double>(scan.size());
    if (s_.laser.people > 0) {
      const std::vector<uint8_t> stopped = people_returns(laser_, st.truth, scan);
      hidden_ = static_cast<size_t>(std::count(stopped.begin(), stopped.end(), 1));
      in_view_ = laser_.people_in_view(st.truth);
    }
    update_filter(*filter_, scan, compass_reading(st.truth, s_.compass_sd, filter_->options().compass_half_width, rng_),
                  told_people(laser_, s_, st.truth, scan));
    estimate_ = filter_->estimate().pose;
    detector_.update(scan_evidence(*world_, estimate_, beams_, scan, s_.lost), st.odometry);
    return st.driven;
  }
  // Moved without odometry: from here on the driver starts at `to`.
  void kidnap(const Pose& to) { driver_ = std::make_unique<WanderDriver>(world_, to, trial_drive(s_), rng_()); truth_ = to; }

  const TrialSettings& s_;
  std::shared_ptr<const RayCaster> world_;
  std::vector<double> beams_;
  std::mt19937_64 rng_;
  LaserSimulator laser_;
  std::unique_ptr<WanderDriver> driver_;
  std::unique_ptr<ParticleFilter> filter_;
  LostDetector detector_;
  Pose truth_;
  Pose estimate_;       // the filter's, after the last scan (what the detector judged)
  bool blind_ = false;  // under a tenth of the last scan's beams returned (from a wall or a person)
  size_t in_view_ = 0, hidden_ = 0;  // the last scan's people in view and the beams they stopped
  int off_scans_ = 0;  // scans in a row with the estimate more than 1 m off, nothing said
};

// One scan of driving with no kidnap, where a "lost" is a false alarm. Counted apart where
// the estimate was more than a metre off (a filter that had lost the robot by itself) and
// where it was within bounds (a false alarm proper). After any "lost" the filter starts
// again at the truth, as a recovery would put it (the kidnap trials measure recoveries):
// one slip is one alarm, not one every few scans. A filter more than a metre off for 3 s
// with nothing said is a slip the detector missed.
void judge_scan_without_kidnap(TrackedRobot& robot, KidnapResult& res) {
  ++res.scans_without_kidnap;
  if (robot.blind_) ++res.blind_scans;
  res.people_in_view += robot.in_view_;
  res.beams_hidden += robot.hidden_;
  res.beams_seen += robot.beams_.size();
  const Pose& e = robot.estimate_;
  const double error = distance(e, robot.truth_);
  if (!robot.detector_.lost()) {
    if (error > 1.0) {
      if (++robot.off_scans_ == static_cast<int>(std::lround(3.0 / robot.s_.scan_period_s))) ++res.slips_unsaid;
    } else if (error < 0.3) {
      robot.off_scans_ = 0;
    }
    return;
  }
  ++res.false_alarms;
  if (error > 1.0) ++res.alarms_while_off;
  if (within_bounds(e, robot.truth_)) ++res.alarms_of_right_pose;
  res.alarm_error_m.push_back(error);
  res.alarm_error_deg.push_back(rad2deg(std::fabs(angle_diff(e.theta, robot.truth_.theta))));
  robot.detector_.reset();
  robot.filter_->init_pose(robot.truth_, 0.1, deg2rad(2.0));
  robot.off_scans_ = 0;
}

}  // namespace

KidnapResult run_kidnap_trials(const Map& map, std::shared_ptr<const RayCaster> world, const TrialSettings& s) {
  KidnapResult res;
  const FreeSpace free_space(map);
  const std::vector<double> beams = evenly_spread_angles(s.laser.beams, s.laser.fov);
  const std::shared_ptr<const GlobalSearch> search = make_search(map, s.filter);
  for (int t = 0; t < s.kidnaps; ++t) {
    std::mt19937_64 rng(s.seed * 104729 + t);
    const Pose start = pick_start_pose(free_space, *world, beams, s.min_hit_fraction, 0.5, rng);
    TrackedRobot robot(map, world, s, start, rng());
    double driven = 0;
    while (driven < s.kidnap_after) {
      driven += robot.step();
      judge_scan_without_kidnap(robot, res);
    }
    res.driven_without_kidnap += driven;
    ++res.trials;
    robot.kidnap(pick_start_pose(free_space, *world, beams, s.min_hit_fraction, 0.5, rng));
    int since = 0;
    const int give_up = static_cast<int>(std::ceil(10.0 / s.scan_period_s));  // 10 s
    while (!robot.detector_.lost() && since < give_up) {
      robot.step();
      ++since;
    }
    if (!robot.detector_.lost()) {
      const Pose e = robot.filter_->estimate().pose;
      if (distance(e, robot.truth_) < 0.3 && std::fabs(angle_diff(e.theta, robot.truth_.theta)) < deg2rad(3.0))
        ++res.found_by_itself;
      continue;
    }
    ++res.detected;
    res.detect_updates.push_back(since);
    if (s.recover_updates <= 0) continue;
    // Recovery as at boot (SimRobot::localize): a global filter, a look around.
    const auto t0 = Clock::now();
    ParticleFilterOptions fo = s.filter;
    fo.seed = s.seed * 7919 + t;
    GlobalRunSeeds seeds;
    seeds.drive = rng();
    seeds.laser = rng();
    const GlobalRun run =
        run_global_localization(map, world, search, fo, s, robot.truth_, seeds, rng, s.recover_updates, true);
    if (run.converged_at > 0 && run.within) {
      ++res.recovered;
      res.recover_updates.push_back(run.converged_at);
    } else if (run.converged_at > 0) {
      ++res.wrong;
      res.wrong_error_m.push_back(run.error);
    }
    res.recover_compute_s += seconds_since(t0) - run.explain_seconds;
  }
  // Normal driving, no kidnap: every "lost" is a false alarm.
  if (s.false_alarm_drive > 0) {
    std::mt19937_64 rng(s.seed * 15485863);
    const Pose start = pick_start_pose(free_space, *world, beams, s.min_hit_fraction, 0.5, rng);
    TrackedRobot robot(map, world, s, start, rng());
    double driven = 0;
    while (driven < s.false_alarm_drive) {
      driven += robot.step();
      judge_scan_without_kidnap(robot, res);
    }
    res.driven_without_kidnap += driven;
  }
  return res;
}

void report_kidnap(std::FILE* out, const Map& map, std::shared_ptr<const RayCaster> world, const TrialSettings& s) {
  const auto t0 = Clock::now();
  const KidnapResult k = run_kidnap_trials(map, world, s);
  const double step = DriveOptions{}.step;
  const double hours = k.driven_without_kidnap / step * s.scan_period_s / 3600;
  // The goal's 3 s, in whole scans.
  const auto within_3s = [&](const KidnapResult& r) {
    return static_cast<int>(std::count_if(r.detect_updates.begin(), r.detect_updates.end(),
                                          [&](int n) { return n * s.scan_period_s <= 3.0 + 1e-9; }));
  };
  std::fprintf(out,
               "kidnapping, %d trials (%d people/scan; after %.0f m of tracking, moved to a random place): detected %d "
               "(%.1f %%) in median %.1f s, p95 %.1f s, max %.1f s, %d within 3 s (the goal; a scan every %.2f s), %d undetected but "
               "found again by the tracking filter itself; recovered %d "
               "(%.1f %% of the detected) in median %.1f s, p95 %.1f s of driving, %.2f s of computation each; "
               "wrong %d, no pose reported %d; false alarms %d in %.2f h of driving (%.0f m) (goal 0 per hour), of which %d with the "
               "estimate more than 1 m off (the filter had lost the robot) and %d of a pose within 0.3 m and 3 deg; "
               "slips of more than 1 m not said within 3 s %d; %.1f %% of the scans blind (under a tenth of the beams "
               "returned; a person's return counts); %.0f s\n",
               k.trials, s.laser.people, s.kidnap_after, k.detected, 100.0 * k.detected / std::max(1, k.trials),
               percentile(k.detect_updates, 0.5) * s.scan_period_s, percentile(k.detect_updates, 0.95) * s.scan_period_s,
               k.detect_updates.empty() ? NAN : *std::max_element(k.detect_updates.begin(), k.detect_updates.end()) * s.scan_period_s,
               within_3s(k), s.scan_period_s, k.found_by_itself, k.recovered, 100.0 * k.recovered / std::max(1, k.detected),
               percentile(k.recover_updates, 0.5) * s.scan_period_s, percentile(k.recover_updates, 0.95) * s.scan_period_s,
               k.recover_compute_s / std::max(1, k.detected), k.wrong,
               s.recover_updates > 0 ? k.detected - k.recovered - k.wrong : 0, k.false_alarms, hours, k.driven_without_kidnap,
               k.alarms_while_off, k.alarms_of_right_pose, k.slips_unsaid,
               100.0 * k.blind_scans / std::max(1, k.scans_without_kidnap), seconds_since(t0));
  if (s.laser.people > 0 && k.scans_without_kidnap > 0)
    std::fprintf(out,
                 "  people in view per scan (the driving without a kidnap): mean %.1f of %d, stopping %.1f %% of the "
                 "beams (0.3 m or more short of the wall behind)\n",
                 static_cast<double>(k.people_in_view) / k.scans_without_kidnap, s.laser.people,
                 100.0 * k.beams_hidden / std::max<size_t>(1, k.beams_seen));
  // The detector's baselines in the same run: the same kidnaps, detection only (no hour
  // of driving), with a rule of the detector undone.
  const auto detection_baseline = [&](const char* what, const auto& undo) {
    TrialSettings before = s;
    undo(before.lost);
    before.recover_updates = 0;
    before.false_alarm_drive = 0;
    const KidnapResult b = run_kidnap_trials(map, world, before);
    std::fprintf(out, "  baseline, %s: detected %d of %d, median %.1f s, max %.1f s, %d within 3 s\n", what, b.detected,
                 b.trials, percentile(b.detect_updates, 0.5) * s.scan_period_s,
                 percentile(b.detect_updates, 1.0) * s.scan_period_s, within_3s(b));
  };
  if (s.kidnaps > 0 && s.lost.count_unmapped_walls)
    detection_baseline("the detector leaving every beam stopped short out (--lost-unmapped-walls 0)",
                       [](LostDetectorOptions& o) { o.count_unmapped_walls = false; });
  if (s.kidnaps > 0 && s.lost.min_telling_beams > 0)
    detection_baseline("a scan on which no beam tells counted as full agreement (--lost-min-telling 0)",
                       [](LostDetectorOptions& o) { o.min_telling_beams = 0; });
  if (s.kidnaps > 0 && s.lost.hold_against > 1)
    detection_baseline("one scan below the floor, then blind ones, enough to say lost (--lost-hold-against 1)",
                       [](LostDetectorOptions& o) { o.hold_against = 1; });
  if (s.kidnaps > 0 && s.lost.unmapped_wall_seen_through > 0)
    detection_baseline("a wall the map lacks counted though an earlier scan saw through it (--lost-wall-seen-through 0)",
                       [](LostDetectorOptions& o) { o.unmapped_wall_seen_through = 0; });
  if (s.kidnaps > 0 && (s.lost.open_beam_weight < 1 || s.lost.fast_alpha != 0.3))
    detection_baseline("open beams counted whole and the fast average at 0.3 (--lost-open-weight 1 --lost-fast-alpha 0.3)",
                       [](LostDetectorOptions& o) {
                         o.open_beam_weight = 1;
                         o.fast_alpha = 0.3;
                       });
  if (s.report_after > 1 && s.recover_updates > 0 && k.detected > 0) {
    // The recovery's baseline in the same run: the pose reported at the first scan on
    // which the cloud has converged with no look-alike place (report_gate.h).
    TrialSettings first = s;
    first.report_after = 1;
    first.false_alarm_drive = 0;
    const KidnapResult b = run_kidnap_trials(map, world, first);
    std::fprintf(out,
                 "  baseline, the pose reported at the first settled scan (--report-after 1): recovered %d, wrong %d, "
                 "no pose reported %d, of %d detected\n",
                 b.recovered, b.wrong, b.detected - b.recovered - b.wrong, b.detected);
  }
  for (size_t i = 0; i < k.wrong_error_m.size(); ++i)
    std::fprintf(out, "  wrong recovery %zu: the reported pose %.2f m off (out of 0.3 m and 3 deg)\n", i + 1,
                 k.wrong_error_m[i]);
  for (size_t i = 0; i < k.alarm_error_m.size(); ++i)
    std::fprintf(out, "  false alarm %zu: the estimate %.2f m and %.1f deg off\n", i + 1, k.alarm_error_m[i],
                 k.alarm_error_deg[i]);
  std::fflush(out);
}

const std::vector<std::string>& preset_names() {
  static const std::vector<std::string> names{"seed", "robust", "search", "fast"};
  return names;
}

std::optional<ParticleFilterOptions> preset(const std::string& name) {
  if (name == "seed") return ParticleFilterOptions::seed_model();
  if (name == "robust") return ParticleFilterOptions::robust();
  if (name == "search") return ParticleFilterOptions::robust_search();
  if (name == "fast") return ParticleFilterOptions::fast_search();
  return std::nullopt;
}

Map load_map_file(const std::string& path) {
  if (std::optional<Map> generated = generated_map_from_name(path)) return std::move(*generated);
  return read_map_file(path);
}

void report_map_header(std::FILE* out, const std::string& path, const Map& map, const TrialSettings& s) {
  const Rect r = map.border.rect();
  std::fprintf(out,
               "\n== %s: %zu segments, border %.0f x %.0f m (%.0f m2); NP %zu, NL %d, RMAX %.0f m, sigma_L %.2f m, "
               "alpha %.2g, beta %.2g, sigma_m %.2g m, %d threads\n",
               path.c_str(), map.segment_count(), r.xmax - r.xmin, r.ymax - r.ymin,
               (r.xmax - r.xmin) * (r.ymax - r.ymin), s.filter.particles, s.filter.beams, s.filter.laser.rmax,
               s.laser.sigma, s.filter.sensor.alpha, s.filter.sensor.beta, s.filter.sensor.sigma_m, s.filter.threads);
  std::fprintf(out, "seed 000 Fig. 5 (the figure to compare with): one simulated run on 10 000 m2, converged in 4 "
                    "iterations; no success rate, tracking error or rate given\n");
}

namespace {

// ", 0.5 m while localizing globally" where the global phase has a value of its own.
std::string global_short_beyond_note(const ParticleFilterOptions& f) {
  if (!(f.global_short_beyond >= 0) || f.global_short_beyond == f.sensor.short_beyond) return "";
  char note[64];
  std::snprintf(note, sizeof note, ", %.2g m while localizing globally", f.global_short_beyond);
  return note;
}

}  // namespace

ParticleFilterOptions trial_filter(const TrialSettings& base, const std::string& name) {
  ParticleFilterOptions f = preset(name).value_or(base.filter);
  f.particles = base.filter.particles;
  f.threads = base.filter.threads;
  f.kld.max_particles = base.filter.particles;
  if (base.short_beyond >= 0) f.sensor.short_beyond = f.global_short_beyond = base.short_beyond;
  if (base.global_short_beyond >= 0) f.global_short_beyond = base.global_short_beyond;
  if (base.short_only_foreground >= 0) f.sensor.short_only_foreground = base.short_only_foreground > 0;
  if (name == "seed") return f;  // the baseline printed beside the others stays the seed's method
  if (base.search_updates >= 0) f.search_updates = static_cast<size_t>(base.search_updates);
  if (base.search_candidates > 0) f.search_candidates = base.search_candidates;
  if (base.search_clusters > 0) f.search_clusters = base.search_clusters;
  if (base.search_particles > 0) f.search_particles = base.search_particles;
  if (base.tempering_ess >= 0) f.tempering_ess = base.tempering_ess;
  if (base.tempering_stages >= 0) f.tempering_stages = base.tempering_stages;
  if (base.settle_after >= 0) f.settle_after = static_cast<size_t>(base.settle_after);
  if (base.search_sigma > 0) f.search.sigma = base.search_sigma;
  if (base.search_max_penalty > 0) f.search.max_penalty = base.search_max_penalty;
  if (base.search_short_only_foreground >= 0) f.search_short_only_foreground = base.search_short_only_foreground > 0;
  if (base.search_drops_foreground >= 0) f.search_drops_foreground = base.search_drops_foreground > 0;
  if (base.foreground_width > 0) f.foreground.max_width = base.foreground_width;
  if (base.rivals >= 0) f.ambiguity.rivals = base.rivals > 0;
  if (base.drop_ruled_out_rivals >= 0) f.ambiguity.drop_ruled_out_rivals = base.drop_ruled_out_rivals > 0;
  if (base.rival_drop_margin_z2 >= 0) f.ambiguity.rival_drop_margin_z2 = base.rival_drop_margin_z2;
  if (base.register_scans >= 0) f.ambiguity.register_scans = base.register_scans > 0;
  if (base.register_moves_place >= 0) f.ambiguity.register_moves_place = base.register_moves_place > 0;
  if (base.rival_margin_z2 >= 0) f.ambiguity.rival_margin_z2 = base.rival_margin_z2;
  if (base.candidates_by_residual >= 0) f.ambiguity.candidates_by_residual = base.candidates_by_residual > 0;
  if (base.turn_in_place_sds >= 0) f.turn_in_place_sds = base.turn_in_place_sds;
  if (base.roughening_max_xy >= 0) f.roughening_max_xy = base.roughening_max_xy;
  if (base.roughening_stage_decay >= 0) f.roughening_stage_decay = base.roughening_stage_decay;
  if (base.kld_min_particles > 0) f.kld.min_particles = base.kld_min_particles;
  if (base.tracking_min_particles > 0) f.tracking_min_particles = base.tracking_min_particles;
  if (base.tracking_sigma_m > 0) f.tracking_sigma_m = base.tracking_sigma_m;
  if (base.kld_bin_xy > 0) f.kld.bin_xy = base.kld_bin_xy;
  if (base.kld_bin_theta_deg > 0) f.kld.bin_theta = deg2rad(base.kld_bin_theta_deg);
  return f;
}

std::optional<GlobalResult> report_preset(std::FILE* out, const Map& map, std::shared_ptr<const RayCaster> world,
                                          const TrialSettings& base, const std::string& name, bool global,
                                          bool tracking) {
  TrialSettings s = base;
  s.filter = trial_filter(base, name);
  const ParticleFilterOptions& f = s.filter;
  std::fprintf(out,
               "-- %s: %s, gamma %.2g, short beyond %.2g m%s%s, tempering ESS %.2g x %d stages, init density %.2g /m2, "
               "roughening %.2g (x %.2g per stage, cap %.2g m)%s%s%s\n",
               name.c_str(), describe(f), f.sensor.gamma, f.sensor.short_beyond,
               f.sensor.short_only_foreground ? " (foreground only)" : "",
               global_short_beyond_note(f).c_str(), f.tempering_ess, f.tempering_stages,
               f.global_density, f.roughening, f.roughening_stage_decay, f.roughening_max_xy,
               f.global_search ? ", global search (likelihood field, ray-cast rerank)" : "",
               f.global_search && f.search_drops_foreground ? ", foreground left out of the search" : "",
               f.global_search && f.search_short_only_foreground ? ", searched cloud: short only in front" : "");
  std::fflush(out);
  std::optional<GlobalResult> result;
  if (global) {
    const GlobalResult g = run_global_trials(map, world, s);
    result = g;
    std::vector<double> errs = g.final_error;
    std::sort(errs.begin(), errs.end());
    std::vector<double> times = g.trial_seconds;
    std::sort(times.begin(), times.end());
    char setup[128] = "";
    if (!times.empty())
      std::snprintf(setup, sizeof setup, " (p50 %.2f s, p95 %.2f s)", times[times.size() / 2],
                    times[std::min(times.size() - 1, times.size() * 95 / 100)]);
    if (f.global_search)
      std::snprintf(setup + std::strlen(setup), sizeof setup - std::strlen(setup), " + %.2f s once per map (field)",
                    g.setup_seconds);
    std::fprintf(out,
                 "global localization, %d trials (%d people/scan%s; %d turns of %.0f deg in place, then %.2g m steps): "
                 "%.1f %% within 0.3 m and 3 deg after <= %d updates "
                 "(goal >= 95 %%); first within at update median %.0f, p90 %.0f; final error median %.2f m; "
                 "%.2f s per localization (%d updates)%s\n",
                 g.trials, s.laser.people, s.exact_people && s.laser.people > 0 ? ", flagged exactly" : "",
                 s.look_around, rad2deg(s.look_around_turn), s.global_step,
                 100.0 * g.converged / std::max(1, g.trials), s.updates,
                 percentile(g.first_within, 0.5), percentile(g.first_within, 0.9),
                 errs.empty() ? NAN : errs[errs.size() / 2], g.seconds / std::max(1, g.trials), s.updates,
                 setup);
    std::fprintf(out,
                 "  outcome: success %d, ambiguous %d (the filter says it cannot tell), wrong %d of %d; weight rule "
                 "(ambiguity.h) on the same trials: success %d, ambiguous %d, wrong %d\n",
                 g.success, g.ambiguous, g.wrong, g.trials, g.success_weight_rule, g.ambiguous_weight_rule,
                 g.wrong_weight_rule);
    if (g.twins_checked)
      std::fprintf(out,
                   "  starts with a twin (another place whose noiseless scans along the same path differ by an RMS "
                   "under a third of the noise; twin_places.h): %d of %d, on which ambiguous %d (right), success %d "
                   "(a lucky pick), wrong %d; on the others success %d, ambiguous %d, wrong %d; right answers %.1f %%; of "
                   "the twins, %d are a place the verdict named that the oracle's search missed (without them: right "
                   "answers %.1f %%)\n",
                   g.twin_starts, g.trials, g.twin_ambiguous, g.twin_success, g.twin_wrong, g.success - g.twin_success,
                   g.ambiguous - g.twin_ambiguous, g.wrong - g.twin_wrong, 100.0 * g.right() / std::max(1, g.trials),
                   g.twins_named_by_verdict, 100.0 * (g.right() - g.twins_named_by_verdict) / std::max(1, g.trials));
    if (g.twins_checked) {
      const NearTwins near = g.near_twins();
      std::fprintf(out,
                   "  near twins (no twin, but another place within an RMS of 0.7 of the noise): %d of %d, on which "
                   "success %d, ambiguous %d, wrong %d; with either the pose or \"ambiguous\" right on them (a "
                   "wrong pose still wrong): right answers %.1f %%\n",
                   near.starts, g.trials, near.success, near.ambiguous, near.wrong,
                   100.0 * (g.right() + near.ambiguous) / std::max(1, g.trials));
    }
    if (g.twins_in_crowd_checked)
      std::fprintf(out,
                   "  twins on what the people left to see (on a beam a person stopped, only a wall in front of "
                   "the person tells a place from the truth): %d of %d, on which ambiguous %d, success %d; right "
                   "answers %.1f %% (%.1f %% on the map alone)\n",
                   g.crowd_twin_starts, g.trials, g.crowd_twin_ambiguous, g.crowd_twin_success,
                   100.0 * g.right_in_crowd() / std::max(1, g.trials), 100.0 * g.right() / std::max(1, g.trials));
    if (s.explain)
      std::fprintf(out,
                   "  out of bounds at the end: %d; the scans favour the estimate in %d (a wrong place fits them "
                   "better: no filter on this model picks the truth), the truth in %d (the filter lost it), "
                   "neither (within %.3f per beam) in %d\n",
                   g.favour_estimate + g.favour_tie + g.favour_truth, g.favour_estimate, g.favour_truth, kFitTie,
                   g.favour_tie);
    if (s.explain && s.laser.people > 0)
      std::fprintf(out, "  people stopped %.1f %% of the beams (0.3 m or more short of the wall behind)\n",
                   100.0 * g.beams_hidden / std::max<size_t>(1, g.beams_seen));
    if (s.explain && f.global_search)
      std::fprintf(out,
                   "  of those, the last global search had the truth among the %zu candidates that get particles in "
                   "%d, ranked lower on cast rays in %d, not among its %zu candidates in %d\n",
                   f.search_clusters, g.truth_in_clusters, g.truth_ranked_out, f.search_candidates, g.truth_not_found);
    // Baselines in the same run: the same trials as the filter has them without the setting.
    const auto baseline = [&](const char* what, TrialSettings b) {
      b.per_trial = nullptr;
      b.explain = false;
      const GlobalResult r = run_global_trials(map, world, b);
      std::fprintf(out, "  baseline, %s: right answers %.1f %%; success %d, ambiguous %d, wrong %d of %d", what,
                   100.0 * r.right() / std::max(1, r.trials), r.success, r.ambiguous, r.wrong, r.trials);
      if (r.twins_in_crowd_checked)
        std::fprintf(out, "; twins on what the people left to see %d, right answers %.1f %%", r.crowd_twin_starts,
                     100.0 * r.right_in_crowd() / std::max(1, r.trials));
      std::fprintf(out, "\n");
    };
    if (s.exact_people && s.laser.people > 0) {
      TrialSettings b = s;
      b.exact_people = false;
      baseline("the people guessed by the filter (foreground.h)", b);
    }
    if (s.laser.people_field > 0 && s.laser.people > 0) {
      TrialSettings b = s;
      b.laser.people_field = 0;
      baseline("every person in the laser's view in every scan (--people-field 0)", b);
    }
    if (f.ambiguity.drop_ruled_out_rivals) {
      TrialSettings b = s;
      b.filter.ambiguity.drop_ruled_out_rivals = false;
      baseline("the rivals judged anew on every window (--drop-ruled-out-rivals 0)", b);
    }
    std::fflush(out);
  }
  if (tracking) {
    for (bool adaptive : {false, true}) {
      if (!adaptive && !s.tracking_fixed) continue;
      const TrackResult t = run_tracking_trial(map, world, s, adaptive);
      char kind[64] = "fixed NP    ";
      if (adaptive)
        std::snprintf(kind, sizeof kind, "KLD adaptive (at least %zu, sigma_m %.2g m)",
                      f.tracking_kld().min_particles, f.tracking_sigma());
      std::fprintf(out,
                   "tracking %s, %.0f m, %d updates: RMS %.3f m (goal < 0.10 m), max %.3f m, RMS heading %.2f deg, "
                   "mean %.0f particles, %.1f Hz\n",
                   kind, t.driven, t.updates, t.rms, t.max,
                   rad2deg(t.rms_theta), t.mean_particles, t.updates / t.seconds);
      if (!adaptive || !s.tracking_fixed)  // the baseline, once per drive
        std::fprintf(out, "  baseline: dead reckoning on the same odometry: RMS %.3f m, final %.3f m\n",
                     t.dead_reckoning_rms, t.dead_reckoning_final);
      std::fflush(out);
    }
  }
  return result;
}

Favoured favoured(const GlobalTrial& t, double tie) {
  if (std::isnan(t.truth_fit) || std::isnan(t.estimate_fit)) return Favoured::Unexplained;
  if (t.estimate_fit > t.truth_fit + tie) return Favoured::Estimate;
  if (t.truth_fit > t.estimate_fit + tie) return Favoured::Truth;
  return Favoured::Tie;
}

bool near_twin(const GlobalTrial& t, double line) { return t.twin == 0 && t.twin_mean_z2 <= line; }

NearTwins GlobalResult::near_twins(double line) const {
  NearTwins n;
  for (const GlobalTrial& t : per_trial) {
    if (!near_twin(t, line)) continue;
    ++n.starts;
    n.success += t.outcome == TrialOutcome::Success;
    n.ambiguous += t.outcome == TrialOutcome::Ambiguous;
    n.wrong += t.outcome == TrialOutcome::Wrong;
  }
  return n;
}

const char* to_string(Favoured f) {
  switch (f) {
    case Favoured::Estimate: return "the estimate";
    case Favoured::Tie: return "neither";
    case Favoured::Truth: return "the truth";
    case Favoured::Unexplained: return "-";
  }
  return "?";
}

const char* to_string(TrialOutcome o) {
  switch (o) {
    case TrialOutcome::Success: return "success";
    case TrialOutcome::Ambiguous: return "ambiguous";
    case TrialOutcome::Wrong: return "wrong";
  }
  return "?";
}

namespace {

double percentile_of(std::vector<double> v, double q) {
  if (v.empty()) return NAN;
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, static_cast<size_t>(q * v.size()))];
}

}  // namespace

void print_table(std::FILE* out, const std::vector<TableRow>& rows) {
  std::fprintf(out, "\n| map | config | trials | success | ambiguous | wrong | weight rule: success / ambiguous / wrong "
                    "| within, no verdict | starts with a twin | right answer | time p50 | time p95 |\n"
                    "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |\n");
  for (const TableRow& r : rows) {
    const GlobalResult& g = r.result;
    std::vector<double> seconds;
    for (const GlobalTrial& t : g.per_trial) seconds.push_back(t.seconds);
    const double n = std::max(1, g.trials);
    // The right answer: success where the start has no twin, ambiguous where it has one.
    char twins[32] = "-", right[32] = "-";
    if (g.twins_checked) {
      std::snprintf(twins, sizeof twins, "%.1f %%", 100.0 * g.twin_starts / n);
      std::snprintf(right, sizeof right, "%.1f %%", 100.0 * g.right() / n);
    }
    std::fprintf(out,
                 "| %s | %s | %d | %.1f %% | %.1f %% | %.1f %% | %.1f / %.1f / %.1f %% | %.1f %% | %s | %s | %.2f s | %.2f s |\n",
                 r.map.c_str(), r.config.c_str(), g.trials, 100.0 * g.success / n, 100.0 * g.ambiguous / n,
                 100.0 * g.wrong / n, 100.0 * g.success_weight_rule / n, 100.0 * g.ambiguous_weight_rule / n,
                 100.0 * g.wrong_weight_rule / n, 100.0 * g.converged / n, twins, right, percentile_of(seconds, 0.5),
                 percentile_of(seconds, 0.95));
  }
  std::fflush(out);
}

void write_trials_csv(std::FILE* out, const std::vector<TableRow>& rows, uint64_t seed) {
  std::fprintf(out, "map,config,seed,trial,start_x,start_y,start_theta_deg,outcome,updates,within_from,places,"
                    "final_error_m,seconds,outcome_weight_rule,places_weight_rule,runner_up_gap,heaviest_gap,truth_fit,"
                    "estimate_fit,search_rank,twin,twin_x,twin_y,twin_mean_z2,twin_named_by_verdict,twin_in_crowd,"
                    "twin_in_crowd_mean_z2\n");
  for (const TableRow& r : rows)
    for (const GlobalTrial& t : r.result.per_trial)
      std::fprintf(out, "%s,%s,%llu,%d,%.3f,%.3f,%.2f,%s,%d,%d,%zu,%.3f,%.3f,%s,%zu,%.4f,%.4f,%.4f,%.4f,%d,%d,%.3f,%.3f,%.4f,%d,%d,%.4f\n",
                   r.map.c_str(),
                   r.config.c_str(), static_cast<unsigned long long>(seed), t.trial, t.start.x, t.start.y,
                   rad2deg(t.start.theta), to_string(t.outcome), t.updates, t.within_from, t.places, t.final_error,
                   t.seconds, to_string(t.outcome_weight_rule), t.places_weight_rule, t.runner_up_gap, t.heaviest_gap,
                   t.truth_fit, t.estimate_fit, t.search_rank, t.twin, t.twin_place.x, t.twin_place.y, t.twin_mean_z2,
                   t.twin_named_by_verdict ? 1 : 0, t.twin_in_crowd, t.twin_in_crowd_mean_z2);
}

}  // namespace fleetmap::localization
