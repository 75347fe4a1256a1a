#pragma once
// Whether a localization trial's start has a twin: another place, at least min_distance
// from it and within the compass's interval of its heading, from which the same path
// (the same turns and steps, in the start's frame) gives the same noiseless scans, up to
// the laser's noise. No filter can tell such a start from its twin, so there the right
// answer is "ambiguous" (SPEC 6 and the localization goals: say so rather than pick
// one); elsewhere it is the pose. The trials score the two kinds of start apart, so that
// a hall of pillars on a grid or a corridor of identical rooms does not count a correct
// "ambiguous" as a failure, nor a lucky pick as a success.
//
// Candidates are the global search's best places (global_search.h) for the truth's
// noiseless scans stitched in the start's frame: a twin scores on the likelihood field
// as the truth does, so it is among the first. Each candidate is refined
// (place_refinement.h) on cast rays and compared beam by beam; only a refined place still
// min_distance from the start counts. The caller may name more candidates (`also`: the
// places a filter's verdict held, carried back to the start): the search's list is a
// heuristic, and a twin it misses is a twin all the same.
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "client/localization/global_search.h"
#include "client/localization/pose.h"
#include "common/raycast/ray_caster.h"

namespace fleetmap::localization {

struct TwinOptions {
  size_t candidates = 30;      // the search's best places tried (0: only `also`)
  double min_distance = 1.0;   // metres from the start: another place, not the start refined
  double sigma = 0.05;         // metres: the laser's noise (seed 000 section 4.1)
  double max_z2 = 9;           // a beam's term: min((difference / sigma)^2, max_z2)
  // A twin when the mean term over every beam of the path is at most this: 0.1 is an
  // RMS difference of a third of the noise (1.6 cm at sigma 0.05 m).
  double twin_mean_z2 = 0.1;
  // A near twin: not a twin, but no other place scores above this (an RMS difference
  // under 0.7 of the noise, 3.5 cm at sigma 0.05 m). On the campus every start the filter
  // missed was one or a twin (docs/localization.md, "The campus's misses are near twins").
  double near_twin_mean_z2 = 0.5;
};

struct TwinCheck {
  bool twin = false;
  // The other place that fits best, refined, and its mean term per beam (infinite when
  // no candidate stayed min_distance away).
  Pose place;
  double mean_z2 = std::numeric_limits<double>::infinity();
  int tried = 0;  // candidates refined
};

// The beams people stopped along a trial's path, one entry per scan of the path. A
// person hides the wall behind it, so on such a beam another place is told from the
// truth only where its own wall stands in front of the person (the reading would then
// be longer than that place allows); elsewhere both explain the reading alike.
struct PeopleInPath {
  std::vector<std::vector<uint8_t>> stopped;  // per beam: 1 where a person stopped it
  std::vector<std::vector<double>> ranges;    // the readings, on those beams the person's
};

// path: the truth's pose at each scan of the trial, path[0] the start; beam_angles and
// world's rmax as the laser's. half_width: the compass's interval either side of the
// start's heading.
// also: more candidate starts, tried after the search's.
// people: given, the beams they stopped are compared as above (a twin on what the
// people left to see); none, or not one scan of every beam per pose of the path, every
// beam on the map alone.
TwinCheck find_twin(const RayCaster& world, const GlobalSearch& search, const std::vector<Pose>& path,
                    const std::vector<double>& beam_angles, double half_width, const TwinOptions& options = {},
                    const std::vector<Pose>& also = {}, const PeopleInPath* people = nullptr);

}  // namespace fleetmap::localization
