#pragma once
// Returns that stand in front of the map: people, carts, anything narrow the map does not
// hold. In a scan they are short runs of beams, narrower than a person or two side by
// side, whose neighbours on both sides reach farther (the range jumps up at each edge).
// This is the segmentation step of the classic laser people detectors (Arras, Martinez
// Mozos & Burgard 2007: break the scan where consecutive ranges jump, then look at each
// segment's width), without their classifier: a narrow segment in front of both
// neighbours is dropped whatever it is.
//
// Why: the global search's likelihood field (global_search.h) charges every end point
// by its distance to the nearest wall. A person in the open costs the true pose the
// field's full floor, so with ten people in view (half the beams) the truth scored far
// below hundreds of wrong places whose points merely fall near some wall: it was never
// among the candidates (docs/localization.md, "Why global localization fails with
// people"). A pillar of the map is dropped too; the walls around it still place the scan.
//
// Segments are peeled from the front: once a segment is dropped its beams count as
// unknown, so a person standing behind another (in front of the wall, behind the first)
// goes next. A segment needs at least one known neighbour, and every known neighbour
// farther than it by `jump`; one that only borders the field of view or other dropped
// segments stays. Walls are wider than max_width, so peeling never reaches them.
#include <cstdint>
#include <vector>

namespace fleetmap::localization {

struct ForegroundOptions {
  double max_width = 1.2;  // metres between a segment's first and last point: two people side by side
  double jump = 0.3;       // metres: consecutive ranges further apart than this break a segment
  int max_rounds = 4;      // peeling rounds (people behind people)
};

// Per beam, 1 where the return is foreground. ranges[j] along beam_angles[j]; a range
// >= rmax (no return) is never foreground and breaks segments.
std::vector<uint8_t> foreground_returns(const std::vector<double>& ranges, const std::vector<double>& beam_angles,
                                        double rmax, const ForegroundOptions& options = {});

}  // namespace fleetmap::localization
