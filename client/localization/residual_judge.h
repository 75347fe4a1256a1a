#pragma once
// The ambiguity verdict's sharper half (ambiguity.h, AmbiguityOptions::rivals): a
// reference place, refined by the residual and, with registered scans, registered there
// (the scans' poses corrected where the stitching's error shows), and other places judged
// against it. A place alike along the path fits those same poses (a twin shares the
// path's geometry), so the others are refined and judged on them as a whole.
#include <cstddef>
#include <vector>

#include "client/localization/ambiguity.h"
#include "client/localization/place_refinement.h"

namespace fleetmap::localization {

// Whether q lies within `separation` of one of the places: then it is that place.
inline bool near_any(const std::vector<Pose>& places, const Pose& q, double separation) {
  for (const Pose& p : places)
    if (distance(p, q) <= separation) return true;
  return false;
}

class ResidualJudge {
 public:
  struct Reference {
    RefinedPlace place;  // score: its fit by the residual (registered, when given)
    PlaceScore judge;    // what the others are refined and judged on
  };
  struct Kept {
    size_t other;  // index in the places judged
    Pose place;    // refined
  };

  // registered may be empty: the residual on the stitched scans alone.
  ResidualJudge(const AmbiguityOptions& options, PlaceScore residual, RegisteredResidual registered);

  // A place refined by residual, then registered there without moving.
  Reference reference_at(const Pose& place) const;
  // The place with the scans registered at it. Moved (register_moves_place), first to
  // where they fit best, each pose tried registered anew; its judge then refers to the
  // latest scan's registered pose. Unmoved, the scans keep their poses relative to it.
  Reference register_at(const Pose& place, bool move) const;

  // The others that are places beside the reference, in order: each refined on the
  // reference's judge (or it would beat the reference by refinement alone) and within
  // rival_margin_z2, or registered at itself at least as good as the reference (the
  // reference may be the wrong one of the two). One not apart (min_separation) from
  // `held`, the reference or a place kept before it is that place. moved: the reference
  // was moved, and plain_kept are the places kept against it unmoved, each moved too
  // before it can be dropped.
  std::vector<Kept> judge(const std::vector<Pose>& others, std::vector<Pose> held, const Reference& reference,
                          bool moved = false, const std::vector<Kept>& plain_kept = {}) const;

  // Whether `other` fits worse than the reference by more than `margin` per beam, both
  // refined on the reference's judge and (with registered scans) registered at itself.
  bool ruled_out(const Pose& other, const Reference& reference, double margin) const;

 private:
  AmbiguityOptions o_;  // a copy: a judge may outlive the caller's options
  PlaceScore residual_;
  RegisteredResidual registered_;
  RefineOptions fine_;    // by residual: its peak is narrow
  RefineOptions coarse_;  // moving a place (place_step_xy, place_step_theta)
};

}  // namespace fleetmap::localization
