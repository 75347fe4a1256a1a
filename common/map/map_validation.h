#pragma once
// Rules a map must satisfy whatever its source (seed file, AMRL import, database).
// Each check returns an "expected ..., got ..." message, or nullopt when the input is valid.
#include <optional>
#include <string>
#include <string_view>

#include "common/map/map.h"

namespace fleetmap {

// Largest coordinate magnitude accepted (10 000 km): beyond that a value is a unit or
// typing error, and doubles lose the millimetre.
inline constexpr double kMaxCoordinate = 1e7;
inline constexpr double kMaxHeight = 1000;
inline constexpr size_t kMaxTextBytes = 1024;  // semantic strings and notes (database column)
// An obstacle's semantic holds every attribute of a GIS feature (docs/gis-import.md);
// OSM relations exceed 1 KiB, so obstacles.semantic is a TEXT column.
inline constexpr size_t kMaxObstacleTextBytes = 65535;

// A semantic string: valid UTF-8, no control characters, none of ; # % (they delimit
// the seed format), at most kMaxTextBytes bytes. A free-form text (a note, which runs
// to the end of its line) may hold the delimiters.
std::optional<std::string> check_text(std::string_view text, std::string_view what, bool free_form = false,
                                      size_t max_bytes = kMaxTextBytes);

std::optional<std::string> check_border(const Border& b);

// One segment alone: finite coordinates within range, non-zero length, h, inOut, texts.
std::optional<std::string> check_segment(const Segment& s);

// A window cut out of a map (SPEC 5.4) has obstacles cut at its edge: their chains
// are broken and a staircase may have lost steps, so only per-segment rules and the
// ramp surface are checked there.
enum class MapKind { Whole, Window };

// Shape rules of the obstacle's type (SPEC 3): closed chains for ST 1/3/6, connected
// chains for ST 2/4, the stairs layout of seed 000 Fig. 1, the ramp encoding.
std::optional<std::string> check_shape(const Obstacle& o, MapKind kind = MapKind::Whole);

// Whole map: the above, unique obstacle ids, every segment inside the border.
// Throws std::invalid_argument naming the obstacle (by id and position) and the rule.
void validate_map(const Map& m, MapKind kind = MapKind::Whole);

}  // namespace fleetmap
