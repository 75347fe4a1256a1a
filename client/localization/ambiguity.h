#pragma once
// Ambiguity of a particle set: where places look genuinely alike (identical rooms, a row
// of identical doors), the cloud holds several clusters of comparable weight, and the
// heaviest one is a coin toss. The filter must say so rather than report it as the pose.
//
// Clusters as PoseEstimate::pose's (particle_filter.h): cells of `cell` metres, a
// cluster the 3 x 3 block of cells holding the most weight. The heaviest is taken, its
// cells removed, and the next heaviest block of what is left is taken again, and so on.
// A cluster counts as a place when it holds at least min_ratio of the heaviest's weight
// and its mean is more than min_separation from every place already taken (farther than
// the 0.3 m bounds of a localization and a converged cloud's 0.5 m spread); two places or
// more: ambiguous.
#include <cstddef>
#include <vector>

#include "client/localization/pose.h"

namespace fleetmap::localization {

struct AmbiguityOptions {
  double cell = 1.0;            // metres (ParticleFilterOptions::cluster_cell)
  double min_ratio = 0.1;       // of the heaviest cluster's weight
  double min_separation = 1.0;  // metres between cluster means
  size_t max_places = 8;        // places listed at most
};

struct Ambiguity {
  bool ambiguous() const { return places.size() >= 2; }
  std::vector<Pose> places;      // cluster means (circular mean heading), heaviest first
  std::vector<double> weights;   // their shares of the total weight
};

// Weights need not be normalized; empty or all-zero sets give no place.
Ambiguity find_ambiguity(const std::vector<Pose>& poses, const std::vector<double>& weights,
                         const AmbiguityOptions& options = {});

}  // namespace fleetmap::localization
