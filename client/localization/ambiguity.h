#pragma once
// Ambiguity of a particle set: where places look genuinely alike (identical rooms, a row
// of identical doors), the cloud holds several places, and the heaviest one is a coin
// toss. The filter must say so rather than report it as the pose.
//
// Candidate places, as PoseEstimate::pose's cluster (particle_filter.h): cells of `cell`
// metres, a cluster the 3 x 3 block of cells holding the most weight. The heaviest is
// taken, its cells removed, and the next heaviest block of what is left is taken again,
// and so on. A cluster is a candidate when it holds at least min_ratio of the heaviest's
// weight and its mean is more than min_separation from every candidate already taken
// (farther than the 0.3 m bounds of a localization and a converged cloud's 0.5 m spread).
//
// Two rules decide which candidates are places (two places or more: ambiguous):
//  * Weight (the first rule): every candidate is a place. A weight share reflects the
//    resampling's drift as much as the evidence (in two identical rooms one room's share
//    fell from 0.56 to 0.21 in 8 updates), so a tenth had to count, and on maps with
//    merely similar places (offices, a hall of pillars) a lucky lump of a tenth made
//    trials ambiguous whose heaviest place was right.
//  * Likelihood (the default): the recent scans are scored with the sensor model from
//    each candidate (its mean and its `refine` heaviest particles, the best of them),
//    as a mean log-likelihood per beam, so the margin does not depend on the number of
//    beams or scans. The places are the heaviest candidate (what estimate() reports) and
//    every candidate within margin_per_beam of the best: identical places score alike
//    and stay; a place that explains the scans worse goes, whatever its weight; a
//    heaviest place that explains them worse than another is kept beside it (the
//    weight and the scans disagree: ambiguous). A diffuse cloud (the candidates
//    holding less than diffuse_share of the weight, e.g. just after init_global) is
//    ambiguous whatever the scans say. With a residual given (the rivals' below), the
//    residual decides between the heaviest and the best, and the other candidates are
//    judged as the rivals are (candidates_by_residual).
#include <cstddef>
#include <functional>
#include <limits>
#include <vector>

#include "client/localization/pose.h"

namespace fleetmap::localization {

enum class AmbiguityRule { Weight, Likelihood };

struct AmbiguityOptions {
  AmbiguityRule rule = AmbiguityRule::Likelihood;
  double cell = 1.0;            // metres (ParticleFilterOptions::cluster_cell)
  double min_ratio = 0.1;       // of the heaviest cluster's weight, for a candidate
  double min_separation = 1.0;  // metres between cluster means
  size_t max_places = 8;        // candidates taken at most
  // Likelihood rule. margin_per_beam: chosen on seed 2032's fast trials (docs/localization.md):
  // above every gap of a trial whose heaviest place was wrong yet the best (0.034).
  double margin_per_beam = 0.04;  // log-likelihood per beam
  size_t scans = 10;              // recent scans scored: a look around's and the first steps
  size_t refine = 4;              // heaviest particles of a candidate scored beside its mean
  double diffuse_share = 0.5;     // of the total weight held by the candidates
  // Rivals (Likelihood rule): places outside the cloud, given by the caller (the
  // filter's: the last global search's best distinct places, carried by the odometry
  // since). Resampling can starve one of two identical places of every particle: in a
  // hall of pillars on a grid, 6 of the 11 starts with a twin ended on the wrong one,
  // reported as the pose (docs/localization.md, "Twins"). Each rival is refined to its
  // best pose nearby (place_refinement.h) and compared with the best candidate, refined
  // likewise, so the verdict rests on the scans rather than on what survived.
  //
  // The comparison is sharper than the margin above: by the residual, the mean over the
  // recent beams of min((measured - cast) / rival_sigma)^2, rival_max_z2), a rival is a
  // place when its residual exceeds the best candidate's by at most rival_margin_z2 (0.1:
  // an RMS difference of a third of the laser's noise, the twin oracle's line,
  // client/sim/twin_places.h). The filter's tempered model (the margin above) scored
  // look-alikes on the campus, 1.4-1.9 m along a facade, within 0.005 per beam of the
  // truth; by the residual they are 0.24-1.9 apart.
  //
  // register_scans: the recent scans are placed from the latest by the stitched odometry,
  // whose error raised the truth's residual from 0.4-0.8 (at the true poses) to 1.2-2.0 on
  // the campus, far more than the margin, and let places that are not twins come within
  // it. Each scan is registered at the best candidate (its best pose within
  // register_max_xy and register_max_theta of the stitched one), and the rivals are
  // refined and judged as a whole on those poses. A rival within rival_register_window_z2
  // that, registered at itself, fits at least as well as the best candidate is a place
  // too: then the best candidate may be the wrong one of the two.
  bool rivals = true;
  size_t max_rivals = 7;
  // drop_ruled_out_rivals: a rival that fits worse than the converged cloud's place by
  // more than rival_drop_margin_z2 on a full window of `scans` is dropped for good. The
  // window slides: on a bland stretch of the path (a long straight wall) a place the
  // scans now gone told apart comes back within the margin, and the verdict said
  // ambiguous after 30 updates where it had not after 26. Off: among people the scans
  // may favour a wrong place, and where the cloud held it, the true place was dropped
  // and a pose 52.8 m off reported (docs/localization.md, "Rivals ruled out, and the
  // window that forgets").
  bool drop_ruled_out_rivals = false;
  double rival_drop_margin_z2 = 0.5;
  double rival_sigma = 0.05;   // metres: the laser's noise, sigma_L (seed 000 section 4.1)
  double rival_max_z2 = 9;
  double rival_margin_z2 = 0.1;
  // The filter keeps as rivals the search's places within this of its best, per beam of
  // its rerank (unrefined, on the search's grid: loose).
  double rival_search_margin_per_beam = 0.2;
  bool register_scans = true;
  double rival_register_window_z2 = 1.0;
  double register_max_xy = 0.3, register_max_theta = deg2rad(3.0);
  double register_step_xy = 0.05, register_step_theta = deg2rad(0.5);
  int register_moves = 40;
  // register_moves_place: when the verdict keeps another place, the reference is moved to
  // where its registered scans fit best, and the others are judged again. It is refined
  // with the scans registered anew at each pose tried (steps of place_step_xy and
  // place_step_theta, halved once, at most place_moves moves); a rival registered at
  // itself within the margin below it, or kept against the unmoved reference, is moved
  // likewise, so the reference gains nothing the rival cannot. The residual on the stitched
  // scans, whose headings the odometry puts 1-2 degrees off, left the reference 0.4-0.6 m
  // along a facade from the truth on the campus, beyond the registration's window; there
  // the scans registered at it fit a look-alike within 0.025 per beam of the truth, where
  // the twin oracle puts it 0.19 worse (docs/localization.md, "The reference moved onto
  // its registered scans"). Only then: moving costs tenths of a second.
  // Not among people: when more than move_max_foreground of the recent returns lie in
  // front of the map (foreground.h), the filter does not move (particle_filter.h). With
  // 10 people in the scans on GDC1, moving turned 3 of 50 "ambiguous" into wrong poses,
  // one 23 m off: the truth, moved too, fit 0.05 per beam worse than a wrong place.
  // Nor when the moved reference lies more than move_max_shift (the bounds of a
  // localization) from its cluster's mean, what the filter reports: there the move found
  // the estimate off (GDC1: two starts 0.44 and 0.96 m off became wrong poses).
  bool register_moves_place = true;
  double move_max_foreground = 0.2;
  double move_max_shift = 0.3;
  double place_step_xy = 0.3, place_step_theta = deg2rad(1.5);
  int place_moves = 8;
  // The cloud's candidates other than the heaviest and the best are judged as rivals
  // are (by the residual, registered), rather than by margin_per_beam, when a residual is
  // given.
  bool candidates_by_residual = true;
  int threads = 1;  // refining the rivals (the filter passes its own); the scores must allow it
};

struct Ambiguity {
  bool ambiguous() const { return places.size() >= 2; }
  std::vector<Pose> places;      // cluster means (circular mean heading), heaviest first
  std::vector<double> weights;   // their shares of the total weight
  // Likelihood rule, when two candidates or more were scored (else NaN): per beam, the
  // best candidate's log-likelihood minus the next best's, and minus the heaviest's.
  double runner_up_gap = std::numeric_limits<double>::quiet_NaN();
  double heaviest_gap = std::numeric_limits<double>::quiet_NaN();
};

// The mean log-likelihood per beam of the recent scans seen from a pose (the latest
// scan's pose; ParticleFilter::ambiguity builds it from its scans and sensor model).
using PlaceScore = std::function<double(const Pose&)>;
// The recent scans registered at a place (ParticleFilter::registered_residual): `place`
// is where the latest scan was registered, and `score` the residual's score with the
// latest scan at the pose given and the others where they were registered, relative to
// it (so score(place) is the registered scans' own fit).
struct RegisteredScans {
  Pose place;
  PlaceScore score;
};
using RegisteredResidual = std::function<RegisteredScans(const Pose&)>;

// Weights need not be normalized; empty or all-zero sets give no place. The Weight rule
// (options.rule is not read).
Ambiguity find_ambiguity(const std::vector<Pose>& poses, const std::vector<double>& weights,
                         const AmbiguityOptions& options = {});
// The Likelihood rule with the given score (options.rule is not read). rivals: places
// outside the cloud (AmbiguityOptions::rivals), compared with the best candidate by
// residual (the negated residual of a pose, higher is better); a rival within the margin
// more than min_separation from the others is a place with no weight. registered, when
// given (AmbiguityOptions::register_scans): the residual with the scans registered at a
// place; the rivals are then refined and judged on the scans registered at the best
// candidate (refined on `residual`).
Ambiguity find_ambiguity(const std::vector<Pose>& poses, const std::vector<double>& weights,
                         const AmbiguityOptions& options, const PlaceScore& score,
                         const std::vector<Pose>& rivals = {}, const PlaceScore& residual = {},
                         const RegisteredResidual& registered = {});

}  // namespace fleetmap::localization
