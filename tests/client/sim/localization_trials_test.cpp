// The trials' explanation of their failures (localization_trials.h, TrialSettings::explain):
// whom the scans favour, where the last search put the truth, and how many beams people hid.
#include "client/sim/localization_trials.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>

#include "common/raycast/grid_ray_caster.h"
#include "common/raycast/sweep_ray_caster.h"

namespace fleetmap::localization {
namespace {

struct Trials {
  Map map = load_map_file("gen:offices");
  std::shared_ptr<const RayCaster> world;
  TrialSettings s;
  explicit Trials(const std::string& config) {
    s.filter = preset(config).value();
    world = std::make_shared<GridRayCaster>(map, s.filter.laser);
    s.filter.threads = 1;
    s.trials = 4;
    s.seed = 11;
    s.explain = true;
  }
};

TEST(LocalizationTrials, ExplainScoresTheTruthAndTheEstimateOfEveryTrialOutOfBounds) {
  // The seed's filter with 100 particles over a floor of offices, three updates: most
  // trials end far from the truth, most on a place that explains the scans worse.
  Trials t("seed");
  t.s.filter.particles = 100;
  t.s.updates = 3;
  t.s.look_around = 0;
  const GlobalResult r = run_global_trials(t.map, t.world, t.s);
  int out_of_bounds = 0;
  int far_and_worse = 0;
  for (const GlobalTrial& g : r.per_trial) {
    EXPECT_EQ(g.search_rank, -2) << "the seed's filter never searches";
    if (std::isnan(g.truth_fit)) continue;
    ++out_of_bounds;
    EXPECT_FALSE(std::isnan(g.estimate_fit));
    // favoured() reads the two fits against the tie margin.
    const Favoured f = favoured(g, kFitTie);
    if (g.truth_fit > g.estimate_fit + kFitTie) EXPECT_EQ(f, Favoured::Truth) << "trial " << g.trial;
    else if (g.estimate_fit > g.truth_fit + kFitTie) EXPECT_EQ(f, Favoured::Estimate) << "trial " << g.trial;
    else EXPECT_EQ(f, Favoured::Tie) << "trial " << g.trial;
    // Per beam, on noise of 0.05 m with no people, the truth's best pose scores near the
    // model's peak; most places metres away do not (an identical office may).
    if (g.final_error > 2 && f == Favoured::Truth) ++far_and_worse;
  }
  ASSERT_GE(out_of_bounds, 2) << "the starved filter should fail most trials";
  EXPECT_GE(far_and_worse, 1) << "a far-off estimate that explains the scans worse than the truth";
  EXPECT_EQ(r.favour_estimate + r.favour_tie + r.favour_truth, out_of_bounds);
  EXPECT_EQ(r.truth_in_clusters + r.truth_ranked_out + r.truth_not_found, out_of_bounds);
  EXPECT_EQ(r.beams_seen, 0u) << "no people, nothing counted";
}

TEST(LocalizationTrials, ExplainFindsTheTruthAmongTheSearchsFirstCandidatesWhereItLocalizes) {
  Trials t("fast");
  const GlobalResult r = run_global_trials(t.map, t.world, t.s);
  int successes = 0;
  for (const GlobalTrial& g : r.per_trial) {
    if (g.outcome != TrialOutcome::Success) continue;
    ++successes;
    // The search's candidates are poses of the scan it searched: the truth at that update.
    EXPECT_GE(g.search_rank, 0) << "trial " << g.trial;
    EXPECT_LT(g.search_rank, static_cast<int>(t.s.filter.search_clusters)) << "trial " << g.trial;
    EXPECT_TRUE(std::isnan(g.truth_fit)) << "a trial within bounds needs no explanation";
  }
  EXPECT_GE(successes, 3);
}

TEST(LocalizationTrials, ExplainCountsTheBeamsPeopleHide) {
  Trials t("fast");
  t.s.trials = 2;
  t.s.laser.people = 5;
  const GlobalResult r = run_global_trials(t.map, t.world, t.s);
  ASSERT_EQ(r.beams_seen, 2u * 10 * 131);  // two trials of ten scans
  const double hidden = static_cast<double>(r.beams_hidden) / r.beams_seen;
  // Five people of 0.4-0.6 m within 15 m, in view, hide some beams but not most of them.
  EXPECT_GT(hidden, 0.02);
  EXPECT_LT(hidden, 0.8);
}

// TrialSettings::exact_people hands the filter the people the simulator placed instead
// of foreground.h's guess (which misses some and flags a few door jambs): the same
// trials, with the same draws, end elsewhere.
TEST(LocalizationTrials, ExactPeopleReachTheFilter) {
  Trials t("fast");
  t.s.trials = 2;
  t.s.laser.people = 5;
  t.s.explain = false;
  t.s.twins = false;
  const GlobalResult guessed = run_global_trials(t.map, t.world, t.s);
  t.s.exact_people = true;
  const GlobalResult told = run_global_trials(t.map, t.world, t.s);
  ASSERT_EQ(guessed.per_trial.size(), 2u);
  ASSERT_EQ(told.per_trial.size(), 2u);
  int differ = 0;
  for (size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(guessed.per_trial[i].start.x, told.per_trial[i].start.x);  // the same trial
    differ += guessed.per_trial[i].final_error != told.per_trial[i].final_error;
  }
  EXPECT_GE(differ, 1);
}

// The bench's KLD options reach the filter of every preset but seed; unset, the preset's
// own floor stays (docs/localization.md, "A tracking cloud of 1 000").
TEST(LocalizationTrials, KldOptionsReachTheTrialsFilter) {
  TrialSettings s;
  s.filter = preset("fast").value();
  EXPECT_EQ(trial_filter(s, "fast").kld.min_particles, preset("fast")->kld.min_particles);
  EXPECT_EQ(trial_filter(s, "search").kld.min_particles, preset("search")->kld.min_particles);
  EXPECT_EQ(trial_filter(s, "fast").tracking_min_particles, preset("fast")->tracking_min_particles);
  s.kld_min_particles = 700;
  s.tracking_min_particles = 1;
  s.tracking_sigma_m = 0.2;
  s.kld_bin_xy = 0.25;
  s.kld_bin_theta_deg = 5;
  const ParticleFilterOptions f = trial_filter(s, "fast");
  EXPECT_EQ(f.kld.min_particles, 700u);
  EXPECT_EQ(f.tracking_min_particles, 1u);
  EXPECT_DOUBLE_EQ(f.tracking_sigma(), 0.2);
  EXPECT_DOUBLE_EQ(trial_filter(s, "seed").tracking_sigma(), preset("seed")->sensor.sigma_m);
  EXPECT_DOUBLE_EQ(f.kld.bin_xy, 0.25);
  EXPECT_NEAR(f.kld.bin_theta, 5 * M_PI / 180, 1e-12);
  EXPECT_EQ(trial_filter(s, "seed").kld.min_particles, 500u);  // the baseline stays the seed's
  EXPECT_EQ(trial_filter(s, "seed").tracking_min_particles, 0u);
}

// A near twin is a checked start without a twin whose nearest other place scores at most
// the line: a twin, an unchecked start or one without another place found is none.
TEST(LocalizationTrials, ANearTwinIsNoTwinWithAnotherPlaceWithinTheLine) {
  GlobalTrial t;
  t.twin = 0;
  t.twin_mean_z2 = 0.3;
  EXPECT_TRUE(near_twin(t, 0.5));
  t.twin_mean_z2 = 0.5;
  EXPECT_TRUE(near_twin(t, 0.5));
  t.twin_mean_z2 = 0.51;
  EXPECT_FALSE(near_twin(t, 0.5));
  t.twin_mean_z2 = std::numeric_limits<double>::infinity();  // no other place stayed 1 m away
  EXPECT_FALSE(near_twin(t, 0.5));
  t.twin_mean_z2 = 0.05;
  t.twin = 1;
  EXPECT_FALSE(near_twin(t, 0.5));
  t.twin = -1;  // not checked
  EXPECT_FALSE(near_twin(t, 0.5));
  t.twin_mean_z2 = NAN;
  EXPECT_FALSE(near_twin(t, 0.5));
}

// The near twins are counted from the per-trial rows, by outcome, and only they add
// to the right answer, by their ambiguous verdicts.
TEST(LocalizationTrials, NearTwinsAreCountedByOutcomeAndOnlyTheirAmbiguousAddToTheRightAnswer) {
  GlobalResult r;
  const auto add = [&](int twin, double mean_z2, TrialOutcome outcome) {
    GlobalTrial t;
    t.twin = twin;
    t.twin_mean_z2 = mean_z2;
    t.outcome = outcome;
    r.per_trial.push_back(t);
    ++r.trials;
    r.success += outcome == TrialOutcome::Success;
    r.ambiguous += outcome == TrialOutcome::Ambiguous;
    r.wrong += outcome == TrialOutcome::Wrong;
    if (twin == 1) {
      ++r.twin_starts;
      r.twin_ambiguous += outcome == TrialOutcome::Ambiguous;
    }
  };
  add(1, 0.05, TrialOutcome::Ambiguous);  // a twin: right, and no near twin
  add(0, 0.3, TrialOutcome::Success);
  add(0, 0.4, TrialOutcome::Ambiguous);
  add(0, 0.45, TrialOutcome::Wrong);
  add(0, 2.0, TrialOutcome::Ambiguous);  // far from any other place: wrong either way
  add(-1, NAN, TrialOutcome::Success);
  const NearTwins near = r.near_twins();
  EXPECT_EQ(near.starts, 3);
  EXPECT_EQ(near.success, 1);
  EXPECT_EQ(near.ambiguous, 1);
  EXPECT_EQ(near.wrong, 1);
  EXPECT_EQ(r.right(), 3);              // the twin, and the two successes
  EXPECT_EQ(r.right_near_either(), 4);  // and the near twin called ambiguous
  EXPECT_EQ(r.near_twins(0.35).starts, 1);  // the line is the caller's
}

// In a hall of pillars on a grid, starts with a twin (twin_places.h) are called ambiguous
// once the filter scores the search's places it lost (AmbiguityOptions::rivals); without
// them resampling leaves one of the two and reports it as the pose (6 of 11 on seed 4242).
TEST(LocalizationTrials, TwinStartsInAHallOfPillarsAreCalledAmbiguous) {
  Trials t("fast");
  t.map = load_map_file("gen:hall");
  t.world = make_fast_ray_caster(t.map, t.s.filter.laser);
  t.s.filter.threads = 2;
  t.s.explain = false;
  t.s.twins = true;
  t.s.trials = 6;
  t.s.seed = 4242;
  t.s.filter.ambiguity.rivals = true;
  const GlobalResult on = run_global_trials(t.map, t.world, t.s);
  ASSERT_TRUE(on.twins_checked);
  ASSERT_GE(on.twin_starts, 3);  // the hall's interior: most starts see pillars only
  EXPECT_EQ(on.twin_ambiguous, on.twin_starts);
  EXPECT_EQ(on.twin_wrong, 0);
  for (const GlobalTrial& g : on.per_trial) {
    ASSERT_GE(g.twin, 0);
    // A twin is a step of the pillars' grid away; another place that fits best is not one.
    if (g.twin) EXPECT_LT(g.twin_mean_z2, 0.1) << "trial " << g.trial;
    else EXPECT_GT(g.twin_mean_z2, 0.1) << "trial " << g.trial;
  }
  EXPECT_EQ(on.right(), on.success - on.twin_success + on.twin_ambiguous);
  int near = 0, near_ambiguous = 0;
  for (const GlobalTrial& g : on.per_trial)
    if (g.twin == 0 && g.twin_mean_z2 <= 0.5) {
      ++near;
      near_ambiguous += g.outcome == TrialOutcome::Ambiguous;
    }
  EXPECT_EQ(on.near_twins().starts, near);
  EXPECT_EQ(on.right_near_either(), on.right() + near_ambiguous);
  t.s.filter.ambiguity.rivals = false;
  const GlobalResult off = run_global_trials(t.map, t.world, t.s);
  EXPECT_EQ(off.twin_starts, on.twin_starts);  // the oracle does not depend on the filter
  EXPECT_GT(off.twin_wrong + off.twin_success, 0) << "without rivals some twin start ends on one place";
}

}  // namespace
}  // namespace fleetmap::localization
