#pragma once
// Floor maps generated in code, seeded, for localization trials on maps the filter was
// not tuned on (SPEC 6; docs/localization.md "Maps it was not tuned on"). Each is closed
// by its outer walls, which are the border, so free space is the floor itself:
//
//  * offices:  a 60 m corridor with rooms of seeded widths and door offsets on both sides;
//  * corridor: an 80 m corridor with a door every 4 m into identical 4 m x 4 m rooms on
//              one side, a blank wall on the other: genuinely ambiguous in the middle;
//  * hall:     a 60 m x 40 m hall with 0.6 m pillars on an 8 m grid;
//  * clutter:  a 40 m x 30 m room with 150 short segments (0.3-1.5 m) at seeded places.
//
// Walls are 2.5 m high (above any laser), open chains; pillars closed polygons.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "common/map/map.h"

namespace fleetmap::localization {

const std::vector<std::string>& generated_map_kinds();

// The map of that kind from that seed; nullopt for an unknown kind.
std::optional<Map> generate_map(const std::string& kind, uint64_t seed);

// "gen:KIND" or "gen:KIND:SEED" (seed 1 when not given) names a generated map wherever a
// map file is taken. Throws std::invalid_argument naming the kinds for a bad name; nullopt
// when `name` does not start with "gen:".
std::optional<Map> generated_map_from_name(const std::string& name);

}  // namespace fleetmap::localization
